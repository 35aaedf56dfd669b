package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Platform names as the JVM reports them, and what the window can do on each. */
class NativesTest {
  @Test
  void jvmNamesMapToNativePlatforms() {
    assertThat(Natives.platform("Linux", "amd64")).isEqualTo("linux-x64");
    assertThat(Natives.platform("Linux", "aarch64")).isEqualTo("linux-arm64");
    assertThat(Natives.platform("Windows 11", "amd64")).isEqualTo("windows-x64");
    assertThat(Natives.platform("Mac OS X", "aarch64")).isEqualTo("macos-arm64");
    assertThat(Natives.platform("Mac OS X", "x86_64")).isEqualTo("macos-x64");
    assertThat(Natives.platform("FreeBSD", "amd64")).isEqualTo("freebsd-x64");
  }

  @Test
  void theWindowOpensWhereLwjglAndImguiNativesAreBundled() {
    assertThat(Natives.windowProblem("linux-x64")).isEmpty();
    assertThat(Natives.windowProblem("windows-x64")).isEmpty();
    assertThat(Natives.windowProblem("macos-x64")).isEmpty();
  }

  @Test
  void arm64WithoutImguiNativesGetsAMessageNamingThePlatformAndWhatStillWorks() {
    assertThat(Natives.windowProblem("linux-arm64")).get().asString()
        .contains("linux-arm64").contains("x86-64").contains("headless commands");
    assertThat(Natives.windowProblem("macos-arm64")).get().asString()
        .contains("macos-arm64").contains("Rosetta 2");
  }

  @Test
  void aPlatformWithNoNativesAtAllIsNamed() {
    assertThat(Natives.windowProblem("linux-riscv64")).get().asString()
        .contains("linux-riscv64").contains("no native libraries");
  }

  @Test
  void thisMachineIsOneTheWindowSupports() {
    // CI and this project's machines are linux-x64: the check must not refuse the window there.
    assertThat(Natives.windowProblem(Natives.currentPlatform())).isEmpty();
  }
}
