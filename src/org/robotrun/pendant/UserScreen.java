package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;

/** USER: the MESSAGE[] texts programs wrote, newest at the bottom, as on the controller's user screen. */
final class UserScreen implements Screen {
  @Override
  public String title(Pendant p) {
    return "USER  (program messages)";
  }

  @Override
  public List<String> body(Pendant p) {
    List<String> all = p.control().userMessages();
    List<String> rows = new ArrayList<>();
    if (all.isEmpty()) {
      rows.add("  (no messages: MESSAGE[...] in a program writes here)");
      return rows;
    }
    for (String m : all.subList(Math.max(0, all.size() - Lcd.BODY_ROWS), all.size())) {
      rows.add(" " + m);
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("", "", "", "", "");
  }

  @Override
  public void key(Pendant p, Key k) {
    p.message("USER shows program messages; MENU for other screens");
  }
}
