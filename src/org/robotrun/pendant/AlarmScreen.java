package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.pendant.RobotControl.AlarmEntry;

/** STATUS / ALARM: the active alarm and the history, newest first; RESET clears the active one. */
final class AlarmScreen implements Screen {
  private int top;

  @Override
  public String title(Pendant p) {
    return "ALARM  " + (p.control().activeAlarm().isPresent() ? "(active: RESET clears)" : "(none active)");
  }

  @Override
  public List<String> body(Pendant p) {
    List<String> rows = new ArrayList<>();
    p.control().activeAlarm().ifPresent(a -> Lcd.wrap("ACTIVE: " + a.display(), Lcd.WIDTH - 2).forEach(r -> rows.add(" " + r)));
    rows.add(" History:");
    List<AlarmEntry> h = p.control().alarmHistory();
    if (h.isEmpty()) {
      rows.add("  (empty)");
    }
    top = Math.max(0, Math.min(top, h.size() - 1));
    for (int i = top; i < h.size() && rows.size() < Lcd.BODY_ROWS; i++) {
      rows.add(String.format(java.util.Locale.ROOT, " %3d %s", i + 1, h.get(i).display()));
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("", "", "", "CLEAR", "");
  }

  @Override
  public void key(Pendant p, Key k) {
    switch (k) {
      case UP -> top = Math.max(0, top - 1);
      case DOWN -> top++;
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
