package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.program.Position;

/**
 * SETUP Frames, type Jog Frame: JOGFRAME[1..5], the frames the JGFRM jog coordinates move along
 * (a fixture's edge, say, without a user frame the programs would have to use). Direct entry of
 * X..R; SETIND selects the jog frame JGFRM uses. (A controller also teaches jog frames by three
 * points; here use a user frame's methods and copy the result.)
 */
final class JogFrameScreen implements Screen {
  static final int FRAMES = 5;
  private static final String[] ELEMENT_NAMES = {"X", "Y", "Z", "W", "P", "R"};
  private int cursor;
  private boolean detail;
  private int row = 1;

  private int number() {
    return cursor + 1;
  }

  @Override
  public String title(Pendant p) {
    return detail ? "SETUP Frames  Jog Frame " + number() + "  Direct Entry"
        : "SETUP Frames  Jog Frames  (active: " + p.control().activeJogFrame() + ")";
  }

  @Override
  public List<String> body(Pendant p) {
    List<String> rows = new ArrayList<>();
    if (detail) {
      Position.Cartesian f = p.control().jogFrame(number());
      for (int j = 1; j <= 6; j++) {
        String v = String.format(Locale.ROOT, "%10.3f", f.element(j));
        rows.add((row == j ? ">" : " ") + " " + ELEMENT_NAMES[j - 1] + " " + (row == j ? "{" + v + "}" : v));
      }
      return rows;
    }
    rows.add("      X       Y       Z      W      P      R");
    int active = p.control().activeJogFrame();
    for (int n = 1; n <= FRAMES; n++) {
      Position.Cartesian f = p.control().jogFrame(n);
      rows.add((n == number() ? ">" : " ") + String.format(Locale.ROOT, "%2d%s%7.1f %7.1f %7.1f %6.1f %6.1f %6.1f", n,
          n == active ? "*" : " ", f.xMm(), f.yMm(), f.zMm(), f.wDeg(), f.pDeg(), f.rDeg()));
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return detail ? List.of("", "", "", "", "") : List.of("[TYPE]", "DETAIL", "", "", "SETIND");
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
  public void text(Pendant p, String s) {
    if (detail) {
      edit(p, s);
    } else {
      p.message("Jog frames: DETAIL to enter values");
    }
  }

  @Override
  public void key(Pendant p, Key k) {
    if (detail) {
      switch (k) {
        case UP -> row = Math.max(1, row - 1);
        case DOWN -> row = Math.min(6, row + 1);
        case ENTER -> edit(p, null);
        default -> {
          if (k.keypadChar().isPresent()) {
            edit(p, String.valueOf(k.keypadChar().get()));
          } else {
            p.message("Jog frame: UP/DOWN, ENTER or type a value; PREV returns");
          }
        }
      }
      return;
    }
    switch (k) {
      case UP -> cursor = Math.max(0, cursor - 1);
      case DOWN -> cursor = Math.min(FRAMES - 1, cursor + 1);
      case F1 -> p.frameTypeMenu();
      case F2, ENTER -> {
        detail = true;
        row = 1;
      }
      case F5 -> p.entry("Active jog frame (1-" + FRAMES + "):", Integer.toString(p.control().activeJogFrame()), false,
          t -> {
            Optional<Integer> n = Pendant.parseInt(t, 1, FRAMES);
            if (n.isEmpty()) {
              return Optional.of("Jog frame: enter 1 to " + FRAMES + ", got '" + t.trim() + "'");
            }
            p.control().selectJogFrame(n.get());
            p.message("Jog frame " + n.get() + " active (JGFRM)");
            return Optional.empty();
          });
      default -> p.message("Jog frames: UP/DOWN, F2 DETAIL, F5 SETIND, F1 other frame types");
    }
  }

  private void edit(Pendant p, String typed) {
    int n = number();
    int j = row;
    String field = "JOGFRAME[" + n + "] " + ELEMENT_NAMES[j - 1];
    p.entryOrTyped("Enter value:", typed, "", false, s -> {
      double v;
      try {
        v = j <= 3 ? NumberEntry.coordinateMm(field, s) : NumberEntry.angleDeg(field, s);
      } catch (ExprText.BadText e) {
        return Optional.of(e.getMessage());
      }
      p.control().setJogFrame(n, p.control().jogFrame(n).withElement(j, v));
      return Optional.empty();
    });
  }
}
