package org.robotrun;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Counts the render tests (no headless OpenGL: Mesa missing) and window tests (Xvfb, xauth or
 * xdotool missing) that skipped themselves, and writes the counts to the file named by the system
 * property {@code robotrun.guiSkips} (the build sets it to target/gui-test-skips.txt), so that the
 * build's last lines can say once how many were skipped and what to install
 * ({@code .ci/GuiSkipSummary.java}, run by the verify phase). Registered through
 * META-INF/services; does nothing when the property is not set. In CI these tests fail instead of
 * skipping, so the file stays at zero there. One test JVM (Surefire's default fork) writes it once;
 * the summary removes it after reading, so a later build never shows stale counts.
 */
public final class GuiSkipCounter implements TestExecutionListener {
  private final AtomicInteger render = new AtomicInteger();
  private final AtomicInteger window = new AtomicInteger();

  @Override
  public void executionFinished(TestIdentifier id, TestExecutionResult result) {
    if (result.getStatus() != TestExecutionResult.Status.ABORTED) {
      return;
    }
    String why = result.getThrowable().map(Throwable::getMessage).orElse("");
    why = why == null ? "" : why.toLowerCase(Locale.ROOT);
    // A skipped class counts its tests one by one only when they run; a class aborted in @BeforeAll counts once.
    if (why.contains("opengl")) {
      render.incrementAndGet();
    } else if (why.contains("xvfb") || why.contains("xdotool")) {
      window.incrementAndGet();
    }
  }

  @Override
  public void testPlanExecutionFinished(TestPlan plan) {
    String file = System.getProperty("robotrun.guiSkips");
    if (file == null || file.isBlank()) {
      return;
    }
    try {
      Path p = Path.of(file);
      int r = render.get();
      int w = window.get();
      Files.createDirectories(p.toAbsolutePath().getParent());
      Files.writeString(p, "render=" + r + "\nwindow=" + w + "\n");
    } catch (IOException | NumberFormatException e) {
      throw new UncheckedIOException(new IOException("cannot write " + file + ": " + e.getMessage(), e));
    }
  }
}
