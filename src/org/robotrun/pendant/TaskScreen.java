package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.control.RobotControl.TaskInfo;

/**
 * STATUS Program: the main program and the tasks RUN started, with their state and line (the
 * controller's program status screen). F2 PAUSE and F3 RESUME act on a RUN task, F4 ABORT ends it;
 * FCTN ABORT (ALL) ends everything. docs/production.md.
 */
final class TaskScreen implements Screen {
  private int cursor;

  @Override
  public String title(Pendant p) {
    return "STATUS Program   " + p.control().tasks().size() + " running";
  }

  @Override
  public List<String> body(Pendant p) {
    List<TaskInfo> tasks = p.control().tasks();
    List<String> rows = new ArrayList<>();
    rows.add("   No. Program           State     Line");
    if (tasks.isEmpty()) {
      rows.add("  (no program runs: RUN in a program starts a task)");
      return rows;
    }
    cursor = Math.max(0, Math.min(cursor, tasks.size() - 1));
    for (int i = 0; i < tasks.size() && rows.size() < Lcd.BODY_ROWS; i++) {
      TaskInfo t = tasks.get(i);
      rows.add(String.format(Locale.ROOT, "%s %3d %-17s %-9s %4d%s", i == cursor ? ">" : " ", i + 1, t.program(), t.state(),
          t.line(), t.main() ? "  (main)" : ""));
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("", "PAUSE", "RESUME", "ABORT", "");
  }

  @Override
  public void key(Pendant p, Key k) {
    List<TaskInfo> tasks = p.control().tasks();
    switch (k) {
      case UP -> cursor = Math.max(0, cursor - 1);
      case DOWN -> cursor = Math.min(Math.max(0, tasks.size() - 1), cursor + 1);
      case F2, F3, F4 -> {
        if (tasks.isEmpty()) {
          p.message("No program runs");
          return;
        }
        TaskInfo t = tasks.get(Math.max(0, Math.min(cursor, tasks.size() - 1)));
        if (t.main()) {
          p.message("The main program: HOLD pauses it, FCTN ABORT (ALL) ends it");
          return;
        }
        Result r = switch (k) {
          case F2 -> p.control().pauseTask(t.program(), true);
          case F3 -> p.control().pauseTask(t.program(), false);
          default -> p.control().abortTask(t.program());
        };
        p.message(switch (r) {
          case Result.Ok ok -> t.program() + (k == Key.F2 ? " paused" : k == Key.F3 ? " resumed" : " aborted");
          case Result.Refused no -> no.reason();
        });
      }
      default -> p.message("UP/DOWN choose a task; F2 PAUSE, F3 RESUME, F4 ABORT");
    }
  }
}
