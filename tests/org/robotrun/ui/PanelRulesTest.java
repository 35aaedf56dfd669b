package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.ui.PanelRules.CellUse;
import org.robotrun.ui.PanelRules.Panel;

/** The left column shows a controller panel when the cell uses it, and keeps what the student chose. */
class PanelRulesTest {
  @TempDir Path config;

  @Test
  void freePlayShowsNoneOfTheControllersPanels() {
    for (Panel p : Panel.values()) {
      assertThat(PanelRules.shown(p, CellUse.FREE_PLAY, Map.of())).as(p.title()).isFalse();
    }
  }

  @Test
  void eachPanelComesWithWhatTheCellUses() {
    CellUse exercise = new CellUse(true, false, false, false, false);
    assertThat(PanelRules.used(Panel.OPERATOR, exercise)).isTrue();  // the labs switch to AUTO there
    assertThat(PanelRules.used(Panel.PLC, exercise)).isFalse();
    assertThat(PanelRules.used(Panel.TASKS, exercise)).isFalse();
    assertThat(PanelRules.used(Panel.BG_LOGIC, exercise)).isFalse();

    CellUse production = new CellUse(false, true, false, false, false);
    assertThat(PanelRules.used(Panel.OPERATOR, production)).isTrue();
    assertThat(PanelRules.used(Panel.PLC, production)).isTrue();
    assertThat(PanelRules.used(Panel.BG_LOGIC, production)).isTrue();
    assertThat(PanelRules.used(Panel.TASKS, production)).isFalse();

    CellUse bg = new CellUse(false, false, true, false, false);
    assertThat(PanelRules.used(Panel.BG_LOGIC, bg)).isTrue();
    assertThat(PanelRules.used(Panel.PLC, bg)).isFalse();

    CellUse run = new CellUse(false, false, false, true, false);
    assertThat(PanelRules.used(Panel.TASKS, run)).isTrue();
    assertThat(PanelRules.used(Panel.OPERATOR, run)).isFalse();

    // a student who switched to AUTO sees the switch to come back
    assertThat(PanelRules.used(Panel.OPERATOR, new CellUse(false, false, false, false, true))).isTrue();
  }

  @Test
  void theStudentsChoiceWinsBothWays() {
    CellUse production = new CellUse(false, true, false, false, false);
    assertThat(PanelRules.shown(Panel.PLC, production, Map.of("plc", false))).isFalse();
    assertThat(PanelRules.shown(Panel.TASKS, CellUse.FREE_PLAY, Map.of("tasks", true))).isTrue();
    // a choice about one panel leaves the others to the rules
    assertThat(PanelRules.shown(Panel.BG_LOGIC, production, Map.of("plc", false))).isTrue();
  }

  @Test
  void theChoiceIsKeptInTheWindowSettingsAndResetLayoutForgetsIt() {
    WindowSettings settings = new WindowSettings(Optional.of(config));
    LayoutState s = new LayoutState();
    s.panels.put(Panel.OPERATOR.key(), false);
    s.panels.put(Panel.TASKS.key(), true);
    assertThat(settings.save(s)).isEmpty();
    LayoutState back = settings.load();
    assertThat(back.panels).containsExactlyInAnyOrderEntriesOf(Map.of("operator", false, "tasks", true));
    assertThat(PanelRules.shown(Panel.OPERATOR, new CellUse(true, true, false, false, false), back.panels)).isFalse();
    back.reset();
    assertThat(back.panels).isEmpty();
  }

  @Test
  void anUnreadableChoiceFollowsTheRules() {
    java.util.Properties p = new LayoutState().toProperties();
    p.setProperty("panel.plc", "maybe");
    p.setProperty("panel.nosuch", "true");
    assertThat(LayoutState.fromProperties(p).panels).isEmpty();
  }
}
