package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** When and how the window falls back to Mesa's software renderer. */
class SoftwareGlTest {
  @Test
  void linuxRetriesOnceWithMesaSoftwareRendering() {
    assertThat(SoftwareGl.mayRetry("Linux", Map.of())).isTrue();
    assertThat(SoftwareGl.mayRetry("FreeBSD", Map.of())).isTrue();
    // The retry itself carries the marker: no second retry, no loop.
    assertThat(SoftwareGl.mayRetry("Linux", SoftwareGl.environment())).isFalse();
    // Already software rendering by the user's choice: retrying would change nothing.
    assertThat(SoftwareGl.mayRetry("Linux", Map.of("LIBGL_ALWAYS_SOFTWARE", "1"))).isFalse();
  }

  @Test
  void windowsAndMacosHaveNoMesaToFallBackTo() {
    assertThat(SoftwareGl.mayRetry("Windows 10", Map.of())).isFalse();
    assertThat(SoftwareGl.mayRetry("Mac OS X", Map.of())).isFalse();
  }

  @Test
  void theRetryAsksMesaForLlvmpipeAndMarksItself() {
    Map<String, String> env = SoftwareGl.environment();
    assertThat(env).containsEntry("LIBGL_ALWAYS_SOFTWARE", "1").containsEntry("GALLIUM_DRIVER", "llvmpipe");
    assertThat(SoftwareGl.active(env)).isTrue();
    assertThat(SoftwareGl.active(Map.of())).isFalse();
  }

  @Test
  void theRetryRunsTheSameCommandLine() {
    ProcessHandle.Info info = new FakeInfo(Optional.of("/opt/robotrun/bin/RobotRun"), Optional.of(new String[] {"--scenario", "a b.json"}));
    assertThat(SoftwareGl.commandLine(info)).contains(List.of("/opt/robotrun/bin/RobotRun", "--scenario", "a b.json"));
    assertThat(SoftwareGl.commandLine(new FakeInfo(Optional.empty(), Optional.of(new String[0])))).isEmpty();
    assertThat(SoftwareGl.commandLine(new FakeInfo(Optional.of("/usr/bin/java"), Optional.empty()))).isEmpty();
  }

  @Test
  void thisProcessKnowsItsOwnCommandLine() {
    // The relaunch depends on it; on Linux the JVM reads it from /proc.
    assertThat(SoftwareGl.commandLine(ProcessHandle.current().info())).get()
        .satisfies(cmd -> assertThat(cmd.get(0)).endsWith("java"));
  }

  private record FakeInfo(Optional<String> command, Optional<String[]> arguments) implements ProcessHandle.Info {
    @Override public Optional<String> commandLine() { return Optional.empty(); }
    @Override public Optional<java.time.Instant> startInstant() { return Optional.empty(); }
    @Override public Optional<java.time.Duration> totalCpuDuration() { return Optional.empty(); }
    @Override public Optional<String> user() { return Optional.empty(); }
  }
}
