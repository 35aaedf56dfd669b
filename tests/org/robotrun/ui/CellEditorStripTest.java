package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.world.CellEditor;
import org.robotrun.world.CellEditor.Result;

/** Issue 29: the cell editor's answer shows in the 3D view while it applies, then goes away. */
class CellEditorStripTest {
  private final AtomicLong now = new AtomicLong(1_000_000_000L);
  private final CellEditorPanel panel = panel();

  private CellEditorPanel panel() {
    ScenarioLoad l = ScenarioReader.read(Path.of("scenarios/pick-and-place.json"));
    CellEditorPanel p = new CellEditorPanel(new CellEditor(((ScenarioLoad.Loaded) l).scenario(), (f, s) -> {
      throw new AssertionError("no meshes here");
    }), null);
    p.setClock(now::get);
    return p;
  }

  private void later(double seconds) {
    now.addAndGet((long) (seconds * 1e9));
  }

  @Test
  void aConfirmationShowsAFewSecondsThenGoes() {
    assertThat(panel.stripMessage()).isEmpty();
    panel.report(new Result.Done("imported bracket.stl as fixture bracket1"));
    assertThat(panel.stripMessage()).contains("imported bracket.stl as fixture bracket1");
    later(CellEditorPanel.STRIP_DONE_SECONDS - 0.5);
    assertThat(panel.stripMessage()).isPresent();
    later(1);
    assertThat(panel.stripMessage()).isEmpty();
    // the panel keeps it
    assertThat(panel.message()).isEqualTo("imported bracket.stl as fixture bracket1");
  }

  @Test
  void aRefusalStaysLongerButNotForMinutesAndGoesWithAnotherSelection() {
    panel.report(new Result.Refused("X: expected -100000 to 100000, got 'abc'"));
    later(CellEditorPanel.STRIP_DONE_SECONDS + 1);
    assertThat(panel.stripMessage()).contains("X: expected -100000 to 100000, got 'abc'");
    later(CellEditorPanel.STRIP_ERROR_SECONDS);
    assertThat(panel.stripMessage()).isEmpty();

    panel.report(new Result.Refused("colour: expected #rrggbb"));
    panel.select("table");
    assertThat(panel.stripMessage()).isEmpty();
  }

  @Test
  void theIdleWindowIsWokenWhenTheStripsMessageGoesAway() {
    assertThat(panel.stripExpiresNanos()).isEqualTo(Long.MAX_VALUE);
    panel.report(new Result.Done("table X = 583 mm"));
    long at = panel.stripExpiresNanos();
    assertThat(at).isGreaterThan(now.get());
    now.set(at - 1_000_000L);
    assertThat(panel.stripMessage()).isPresent();
    now.set(at);
    assertThat(panel.stripMessage()).isEmpty();
    assertThat(panel.stripExpiresNanos()).isEqualTo(Long.MAX_VALUE);
  }

  @Test
  void theIdleLoopSleepsUntilTheWakeItWasAskedForWithinItsBounds() {
    long now0 = 5_000_000_000L;
    assertThat(SimulatorWindow.idleSleepSec(now0, Long.MAX_VALUE)).isEqualTo(SimulatorWindow.IDLE_REDRAW_SEC);
    assertThat(SimulatorWindow.idleSleepSec(now0, now0 + 2_500_000_000L)).isEqualTo(2.5);
    assertThat(SimulatorWindow.idleSleepSec(now0, now0 - 1)).isEqualTo(0.001);
    assertThat(SimulatorWindow.idleSleepSec(now0, now0 + 3_600_000_000_000L)).isEqualTo(SimulatorWindow.IDLE_REDRAW_SEC);
  }

  @Test
  void quitSaveAndOpenWorkWhileATextFieldHasTheKeyboardAndItsEditingKeysStayTheFields() {
    assertThat(SimulatorWindow.shortcutWhileTyping(org.lwjgl.glfw.GLFW.GLFW_KEY_Q)).isTrue();
    assertThat(SimulatorWindow.shortcutWhileTyping(org.lwjgl.glfw.GLFW.GLFW_KEY_S)).isTrue();
    assertThat(SimulatorWindow.shortcutWhileTyping(org.lwjgl.glfw.GLFW.GLFW_KEY_O)).isTrue();
    assertThat(SimulatorWindow.shortcutWhileTyping(org.lwjgl.glfw.GLFW.GLFW_KEY_Z)).isFalse();
    assertThat(SimulatorWindow.shortcutWhileTyping(org.lwjgl.glfw.GLFW.GLFW_KEY_H)).isFalse();
  }
}
