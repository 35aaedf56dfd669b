package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class WindowSettingsTest {
  @TempDir Path config;
  @TempDir Path workspaces;

  @Test
  void eachWorkspaceKeepsItsOwnLayoutAndANewOneStartsFromTheLastLayout() {
    WindowSettings user = new WindowSettings(Optional.of(config));
    WindowSettings a = WindowSettings.forWorkspace(user, workspaces.resolve("a"));
    WindowSettings b = WindowSettings.forWorkspace(user, workspaces.resolve("b"));
    assertThat(a.file()).isNotEqualTo(b.file());

    LayoutState wide = new LayoutState();
    wide.pendantWidth = 611;
    wide.welcomeSeen = true;
    assertThat(a.save(wide)).isEmpty();
    LayoutState narrow = new LayoutState();
    narrow.pendantWidth = 433;
    narrow.welcomeSeen = true;
    assertThat(b.save(narrow)).isEmpty();

    assertThat(WindowSettings.forWorkspace(user, workspaces.resolve("a")).load().pendantWidth).isEqualTo(611);
    assertThat(WindowSettings.forWorkspace(user, workspaces.resolve("b")).load().pendantWidth).isEqualTo(433);
    // a workspace never opened before starts from the layout the user left last (b's)
    LayoutState fresh = WindowSettings.forWorkspace(user, workspaces.resolve("c")).load();
    assertThat(fresh.pendantWidth).isEqualTo(433);
    assertThat(fresh.welcomeSeen).isTrue();
  }
}
