package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Each platform's usual folders, the test overrides, and the recent list. */
class UserDirsTest {
  @Test
  void linuxFollowsXdgAndFallsBackToTheHome() {
    assertThat(UserDirs.of(Map.of(), "Linux", "/home/ada").defaultWorkspace())
        .isEqualTo(Path.of("/home/ada/.local/share/robotrun/workspace"));
    assertThat(UserDirs.of(Map.of("XDG_DATA_HOME", "/data", "XDG_CONFIG_HOME", "/cfg"), "Linux", "/home/ada").defaultWorkspace())
        .isEqualTo(Path.of("/data/robotrun/workspace"));
    assertThat(UserDirs.of(Map.of("XDG_CONFIG_HOME", "/cfg"), "Linux", "/home/ada").configDir()).isEqualTo(Path.of("/cfg/robotrun"));
    // XDG: a relative value is ignored
    assertThat(UserDirs.of(Map.of("XDG_DATA_HOME", "rel"), "Linux", "/home/ada").defaultWorkspace())
        .isEqualTo(Path.of("/home/ada/.local/share/robotrun/workspace"));
  }

  @Test
  void macAndWindowsUseTheirApplicationFolders() {
    assertThat(UserDirs.of(Map.of(), "Mac OS X", "/Users/ada").defaultWorkspace())
        .isEqualTo(Path.of("/Users/ada/Library/Application Support/RobotRun/workspace"));
    Path appData = Path.of("/appdata");
    assertThat(UserDirs.of(Map.of("APPDATA", appData.toString()), "Windows 11", "/home").defaultWorkspace())
        .isEqualTo(appData.resolve("RobotRun").resolve("workspace").toAbsolutePath());
  }

  @Test
  void theOverridesKeepTestsAwayFromTheRealHome(@TempDir Path tmp) throws Exception {
    UserDirs d = UserDirs.of(Map.of("ROBOTRUN_DATA_DIR", tmp.resolve("d").toString(), "ROBOTRUN_CONFIG_DIR",
        tmp.resolve("c").toString()), "Linux", "/nonexistent");
    assertThat(d.defaultWorkspace()).isEqualTo(tmp.resolve("d/workspace"));
    assertThat(d.lastWorkspace()).isEmpty();
    Path a = Files.createDirectories(tmp.resolve("a"));
    Path b = Files.createDirectories(tmp.resolve("b"));
    d.remember(a);
    d.remember(b);
    d.remember(a);
    assertThat(d.recentWorkspaces()).containsExactly(a, b);
    assertThat(d.lastWorkspace()).contains(a);
    Files.delete(a);
    assertThat(d.lastWorkspace()).as("a folder that is gone is skipped").contains(b);
    assertThat(d.newWorkspaceFor("pick and place")).isEqualTo(tmp.resolve("d/workspaces/pick_and_place"));
  }
}
