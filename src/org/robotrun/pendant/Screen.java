package org.robotrun.pendant;

import java.util.List;

/**
 * One pendant screen: its title, body rows, function-key labels and how it takes keys. The
 * {@link Pendant} handles the keys every screen shares (screen keys, COORD, override, jog, run
 * control) and hands the rest here. Screens keep their own cursor between visits.
 */
public sealed interface Screen
    permits SelectScreen, EditScreen, PositionScreen, DataScreen, IoScreen, PosnScreen, FrameScreen, JogFrameScreen, AlarmScreen,
        UserScreen, TaskScreen, BgLogicScreen {

  /** The title row. */
  String title(Pendant p);

  /**
   * The title row in at most {@code room} characters (a choice list's name follows it on the same
   * row). A screen whose title can run long shortens its least useful part; by default the end is cut.
   */
  default String title(Pendant p, int room) {
    String t = title(p);
    return t.length() <= room ? t : t.substring(0, Math.max(0, room));
  }

  /** Up to {@link Lcd#BODY_ROWS} rows; the cursor row starts with {@code >}. */
  List<String> body(Pendant p);

  /** Labels of F1..F5 (five entries, "" for an unused key). */
  List<String> functionKeys(Pendant p);

  /** A key the pendant did not handle itself; {@link Pendant#shift()} tells whether SHIFT is on. */
  void key(Pendant p, Key k);

  /** Typed text with no entry open: screens with a text field under the cursor start an entry. */
  default void text(Pendant p, String s) {
    p.message("No text field here: move to a field and press ENTER");
  }

  /** PREV on this screen: true when the screen used it (e.g. detail back to list). */
  default boolean prev(Pendant p) {
    return false;
  }
}
