package org.robotrun.app;

import java.util.Locale;
import java.util.Optional;

/**
 * Which platforms the bundled native libraries cover. LWJGL (GLFW, OpenGL, stb) ships natives for
 * linux x64 and arm64, windows x64 and macos x64 and arm64; imgui-java 1.86.11, which draws the
 * window's panels, publishes x86-64 natives only (Linux, Windows, macOS Intel). On anything else
 * the window says what is missing instead of crashing; headless commands need no natives at all
 * but {@code render}, which needs LWJGL's.
 */
final class Natives {
  private Natives() {}

  /** The platform as the natives name it, e.g. {@code linux-x64}, {@code macos-arm64}. */
  static String platform(String osName, String osArch) {
    String os = osName.toLowerCase(Locale.ROOT);
    String family = os.startsWith("windows") ? "windows"
        : os.startsWith("mac") || os.startsWith("darwin") ? "macos"
        : os.startsWith("linux") ? "linux"
        : os.replace(' ', '_');
    String arch = switch (osArch.toLowerCase(Locale.ROOT)) {
      case "amd64", "x86_64", "x64" -> "x64";
      case "aarch64", "arm64" -> "arm64";
      default -> osArch.toLowerCase(Locale.ROOT);
    };
    return family + "-" + arch;
  }

  static String currentPlatform() {
    return platform(System.getProperty("os.name", "?"), System.getProperty("os.arch", "?"));
  }

  private static boolean hasLwjgl(String platform) {
    return switch (platform) {
      case "linux-x64", "linux-arm64", "windows-x64", "macos-x64", "macos-arm64" -> true;
      default -> false;
    };
  }

  private static boolean hasImgui(String platform) {
    return switch (platform) {
      case "linux-x64", "windows-x64", "macos-x64" -> true;
      default -> false;
    };
  }

  /** Why the window cannot open on this platform, or empty when its natives are bundled. */
  static Optional<String> windowProblem(String platform) {
    if (!hasLwjgl(platform)) {
      return Optional.of("the simulator window has no native libraries for " + platform
          + " (built for linux-x64, linux-arm64, windows-x64, macos-x64, macos-arm64); the headless commands run, check and pendant still work");
    }
    if (!hasImgui(platform)) {
      String hint = platform.startsWith("macos")
          ? "; install the Intel (x64) build of RobotRun, which runs on Apple silicon through Rosetta 2"
          : "";
      return Optional.of("the simulator window needs Dear ImGui natives, which imgui-java publishes for x86-64 only, not for "
          + platform + hint + "; the headless commands (run, check, pendant, render) still work");
    }
    return Optional.empty();
  }
}
