package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.AlarmEntry;
import org.robotrun.program.AlarmCode;

/**
 * STATUS / ALARM: the active alarm and the history, newest first; RESET clears the active one.
 * F5 HELP opens the detail page of the alarm under the cursor (the alarm table: severity, cause
 * and remedy, written for students); PREV comes back.
 */
final class AlarmScreen implements Screen {
  private int top;
  private boolean detail;

  @Override
  public String title(Pendant p) {
    return "ALARM  " + (p.control().activeAlarm().isPresent() ? "(active: RESET clears)" : "(none active)");
  }

  @Override
  public List<String> body(Pendant p) {
    if (detail) {
      return detailBody(p);
    }
    List<String> rows = new ArrayList<>();
    p.control().activeAlarm().ifPresent(a -> Lcd.wrap("ACTIVE: " + a.display(), Lcd.WIDTH - 2).forEach(r -> rows.add(" " + r)));
    rows.add(" History:");
    List<AlarmEntry> h = p.control().alarmHistory();
    if (h.isEmpty()) {
      rows.add("  (empty)");
    }
    top = Math.max(0, Math.min(top, h.size() - 1));
    for (int i = top; i < h.size() && rows.size() < Lcd.BODY_ROWS; i++) {
      rows.add(String.format(java.util.Locale.ROOT, "%s%3d %s", i == top ? ">" : " ", i + 1, h.get(i).display()));
    }
    return rows;
  }

  /** The alarm the detail page shows: the history entry under the cursor, else the active one. */
  private static java.util.Optional<AlarmEntry> selected(Pendant p, int index) {
    List<AlarmEntry> h = p.control().alarmHistory();
    return index < h.size() ? java.util.Optional.of(h.get(index)) : p.control().activeAlarm();
  }

  private List<String> detailBody(Pendant p) {
    List<String> rows = new ArrayList<>();
    java.util.Optional<AlarmEntry> a = selected(p, top);
    if (a.isEmpty()) {
      rows.add(" No alarm to explain");
      return rows;
    }
    Lcd.wrap(a.get().display(), Lcd.WIDTH - 2).forEach(r -> rows.add(" " + r));
    java.util.Optional<AlarmCode> row = AlarmCode.of(a.get().code());
    if (row.isEmpty()) {
      rows.add(" (no entry in the alarm table for " + a.get().code() + ")");
      return rows;
    }
    AlarmCode c = row.get();
    Lcd.wrap("Severity " + c.severity() + ": " + c.severity().effect(), Lcd.WIDTH - 2).forEach(r -> rows.add(" " + r));
    Lcd.wrap("Cause: " + c.cause(), Lcd.WIDTH - 2).forEach(r -> rows.add(" " + r));
    Lcd.wrap("Remedy: " + c.remedy(), Lcd.WIDTH - 2).forEach(r -> rows.add(" " + r));
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return detail ? List.of("", "", "", "", "") : List.of("", "", "", "CLEAR", "HELP");
  }

  @Override
  public boolean prev(Pendant p) {
    if (detail) {
      detail = false;
      return true;
    }
    return false;
  }

  @Override
  public void key(Pendant p, Key k) {
    switch (k) {
      case UP -> top = Math.max(0, top - 1);
      case DOWN -> top++;
      case F5 -> {
        if (!detail && selected(p, top).isEmpty()) {
          p.message("No alarm to explain");
        } else {
          detail = true;
          p.message("Alarm detail: PREV returns to the list");
        }
      }
      case F4 -> {
        if (!p.shift()) {
          p.message("CLEAR history: hold SHIFT and press F4");
        } else {
          p.control().clearAlarmHistory();
          p.message("Alarm history cleared");
        }
      }
      default -> p.message("ALARM: RESET clears the active alarm");
    }
  }
}
