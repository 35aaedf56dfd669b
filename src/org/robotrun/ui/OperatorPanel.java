package org.robotrun.ui;

import imgui.ImGui;
import org.robotrun.control.RobotControl;
import org.robotrun.pendant.Pendant;

/**
 * The controller cabinet's operator panel, drawn as a section of the window's left column: the
 * mode switch (T1 / T2 / AUTO), CYCLE START (runs the selected program in AUTO with the pendant
 * disabled) and the panel's E-stop (SRVO-001).
 */
public final class OperatorPanel {
  /** The section title. */
  public static final String TITLE = PanelRules.Panel.OPERATOR.title();

  private final java.util.function.Supplier<Pendant> pendantNow;

  public OperatorPanel(Pendant pendant) {
    this(() -> pendant);
  }

  /** Drives whichever pendant {@code pendantNow} answers (the robot selector's choice) at each call. */
  public OperatorPanel(java.util.function.Supplier<Pendant> pendantNow) {
    this.pendantNow = pendantNow;
  }

  /** The panel's controls, inside whatever window or section the caller opened. */
  public void drawContents() {
    RobotControl.Mode mode = pendant().control().mode();
    ImGui.textUnformatted("Mode");
    for (RobotControl.Mode m : RobotControl.Mode.values()) {
      ImGui.sameLine();
      if (ImGui.radioButton(m.name() + "##mode", mode == m) && m != mode) {
        pendant().setMode(m);
      }
    }
    SafetySwitches.hint("T1: TCP at most 250 mm/s, hold-to-run; T2: programmed speed, hold-to-run; "
        + "AUTO: run with CYCLE START, pendant off");
    if (ImGui.button("CYCLE START")) {
      pendant().cycleStart();
    }
    SafetySwitches.hint("AUTO only, TP ENABLE off: runs the selected program");
    ImGui.sameLine();
    boolean estop = pendant().control().emergencyStopped();
    if (SafetySwitches.coloured((estop ? "E-STOP (pressed)" : "E-STOP") + "##panelestop", true, 0.8f, 0.1f, 0.1f, 0)) {
      if (estop) {
        pendant().releaseEmergencyStop();
      } else {
        pendant().emergencyStop(false);
      }
    }
    SafetySwitches.hint(estop ? "Click to twist the E-stop out, then RESET" : "Operator panel E-stop (SRVO-001)");
  }

  private Pendant pendant() {
    return pendantNow.get();
  }
}
