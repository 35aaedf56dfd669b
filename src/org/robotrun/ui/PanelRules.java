package org.robotrun.ui;

import java.util.Map;

/**
 * Which of the controller's panels the left column shows: each when the cell uses it, unless the
 * student chose otherwise in the View menu (the choice is kept with the layout). A beginner in
 * free play sees the task, the robot and the cell; the operator panel comes with an exercise or a
 * production setup, or once the mode switch has left T1; the PLC panel with a production setup;
 * the task list once a program RUNs a second task (or one has run); BG Logic when a program is in a BG slot or the
 * cell has a production setup (its exercises add one).
 */
public final class PanelRules {
  private PanelRules() {}

  /** The panels the rules decide, with the title of their section and their key in the layout file. */
  public enum Panel {
    OPERATOR("Operator panel", "operator"),
    PLC("PLC panel (UOP)", "plc"),
    TASKS("Tasks", "tasks"),
    BG_LOGIC("BG Logic", "bgLogic");

    private final String title;
    private final String key;

    Panel(String title, String key) {
      this.title = title;
      this.key = key;
    }

    public String title() {
      return title;
    }

    /** The panel's name in {@link LayoutState}'s properties ({@code panel.KEY}). */
    public String key() {
      return key;
    }
  }

  /**
   * What the cell uses now, over all its robots.
   *
   * @param task the cell is an exercise (it has a task text)
   * @param productionSetup a robot has a "production" setup (UOP, PNS/RSR, a PLC sequence)
   * @param bgPrograms a program is in a BG Logic slot
   * @param tasksRun a program has a RUN statement, or a second task has run since the cell was opened
   * @param modeNotT1 a robot's mode switch is at T2 or AUTO
   */
  public record CellUse(boolean task, boolean productionSetup, boolean bgPrograms, boolean tasksRun, boolean modeNotT1) {
    /** A cell that uses none of the panels: free play. */
    public static final CellUse FREE_PLAY = new CellUse(false, false, false, false, false);
  }

  /** Whether the cell uses {@code panel}. */
  public static boolean used(Panel panel, CellUse use) {
    return switch (panel) {
      case OPERATOR -> use.task() || use.productionSetup() || use.modeNotT1();
      case PLC -> use.productionSetup();
      case TASKS -> use.tasksRun();
      case BG_LOGIC -> use.bgPrograms() || use.productionSetup();
    };
  }

  /** Whether the left column shows {@code panel}: the student's choice when there is one, else {@link #used}. */
  public static boolean shown(Panel panel, CellUse use, Map<String, Boolean> chosen) {
    Boolean c = chosen.get(panel.key());
    return c != null ? c : used(panel, use);
  }
}
