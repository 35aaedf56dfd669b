package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.control.RobotControl.TeachMethod;
import org.robotrun.control.RobotControl.TeachResult;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;

/**
 * SETUP Frames: tool frames 1–10 and user frames 1–10 with comments. DETAIL teaches one frame:
 * pick a method, record each listed point with SHIFT+F5 (the current position), go back to a
 * recorded point with SHIFT+F4 MOVE_TO; when every point is recorded the controller computes the
 * frame and the screen shows it or the reason it failed. Direct entry edits X..R. SETIND (or
 * SHIFT+COORD anywhere) selects the active frame.
 */
final class FrameScreen implements Screen {
  private static final int FRAMES = 10;
  private static final String[] ELEMENT_NAMES = {"X", "Y", "Z", "W", "P", "R"};

  private FrameKind kind = FrameKind.TOOL;
  private final int[] cursor = new int[2];
  private boolean detail;
  /** Detail cursor: 0 comment, 1.. points (or X..R for direct entry). */
  private int row;
  private final Map<String, TeachMethod> methods = new HashMap<>();
  private final Map<String, Position.Joint[]> recorded = new HashMap<>();
  private final Map<String, String> results = new HashMap<>();

  /** Shows tool or user frames. */
  void showKind(FrameKind k) {
    kind = k;
    detail = false;
  }

  private int number() {
    return cursor[kind.ordinal()] + 1;
  }

  private String key() {
    return kind + "/" + number();
  }

  private TeachMethod method() {
    return methods.getOrDefault(key(), TeachMethod.forKind(kind).get(0));
  }

  private Position.Joint[] points() {
    TeachMethod m = method();
    return recorded.computeIfAbsent(key() + "/" + m, k -> new Position.Joint[m.pointNames().size()]);
  }

  private String word() {
    return kind == FrameKind.TOOL ? "Tool" : "User";
  }

  @Override
  public String title(Pendant p) {
    return detail ? "SETUP Frames  " + word() + " Frame " + number() + "  " + method().title()
        : "SETUP Frames  " + word() + " Frames  (active: " + p.control().activeFrame(kind) + ")";
  }

  @Override
  public List<String> body(Pendant p) {
    return detail ? detailBody(p) : listBody(p);
  }

  private List<String> listBody(Pendant p) {
    List<String> rows = new ArrayList<>();
    rows.add("      X       Y       Z      W      P      R   Comment");
    int active = p.control().activeFrame(kind);
    for (int n = 1; n <= FRAMES; n++) {
      Position.Cartesian f = p.control().frame(kind, n);
      rows.add((n == number() ? ">" : " ") + String.format(Locale.ROOT, "%2d%s%7.1f %7.1f %7.1f %6.1f %6.1f %6.1f %s", n,
          n == active ? "*" : " ", f.xMm(), f.yMm(), f.zMm(), f.wDeg(), f.pDeg(), f.rDeg(), p.control().frameComment(kind, n)));
    }
    return rows;
  }

  private List<String> detailBody(Pendant p) {
    List<String> rows = new ArrayList<>();
    String comment = p.control().frameComment(kind, number());
    rows.add((row == 0 ? ">" : " ") + " Comment: " + (row == 0 ? "{" + comment + "}" : comment));
    Position.Cartesian f = p.control().frame(kind, number());
    rows.add(String.format(Locale.ROOT, "  Frame: X %.1f Y %.1f Z %.1f W %.1f P %.1f R %.1f", f.xMm(), f.yMm(), f.zMm(),
        f.wDeg(), f.pDeg(), f.rDeg()));
    TeachMethod m = method();
    if (m.pointNames().isEmpty()) {
      for (int j = 1; j <= 6; j++) {
        String v = String.format(Locale.ROOT, "%10.3f", f.element(j));
        rows.add((row == j ? ">" : " ") + " " + ELEMENT_NAMES[j - 1] + " " + (row == j ? "{" + v + "}" : v));
      }
    } else {
      Position.Joint[] pts = points();
      for (int i = 0; i < pts.length; i++) {
        String state = pts[i] == null ? "UNINIT" : "RECORDED";
        rows.add((row == i + 1 ? ">" : " ") + String.format(Locale.ROOT, " %-22s %s", m.pointNames().get(i) + ":",
            row == i + 1 ? "{" + state + "}" : state));
      }
    }
    String res = results.get(key());
    if (res != null) {
      for (String r : Lcd.wrap(res, Lcd.WIDTH - 2)) {
        rows.add(" " + r);
      }
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return detail ? List.of("", "[METHOD]", "FRAME", "MOVE_TO", "RECORD")
        : List.of("[TYPE]", "DETAIL", "", "CLEAR", "SETIND");
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
    if (detail) {
      detailKey(p, k);
      return;
    }
    int t = kind.ordinal();
    switch (k) {
      case UP -> cursor[t] = Math.max(0, cursor[t] - 1);
      case DOWN -> cursor[t] = Math.min(FRAMES - 1, cursor[t] + 1);
      case F1 -> p.frameTypeMenu();
      case F2, ENTER -> {
        detail = true;
        row = 0;
      }
      case F4 -> p.confirm("Clear " + word() + " Frame " + number() + "?", () -> {
        p.control().setFrame(kind, number(), Position.Cartesian.ZERO);
        results.remove(key());
        p.message(word() + " Frame " + number() + " cleared");
      });
      case F5 -> {
        p.control().selectFrame(kind, number());
        p.message("Active " + (kind == FrameKind.TOOL ? "UTOOL" : "UFRAME") + " = " + number());
      }
      default -> {
        if (k.digit() >= 0) {
          p.message("SETIND (F5) makes the frame under the cursor active");
        }
      }
    }
  }

  private void detailKey(Pendant p, Key k) {
    TeachMethod m = method();
    int last = m.pointNames().isEmpty() ? 6 : m.pointNames().size();
    switch (k) {
      case UP -> row = Math.max(0, row - 1);
      case DOWN -> row = Math.min(last, row + 1);
      case F2 -> {
        List<TeachMethod> ms = TeachMethod.forKind(kind);
        p.choose("METHOD", ms.stream().map(TeachMethod::title).toList(), i -> {
          methods.put(key(), ms.get(i));
          row = 0;
        });
      }
      case F3 -> p.entry(word() + " frame number (1-10):", "", false, s -> {
        Optional<Integer> n = Pendant.parseInt(s, 1, FRAMES);
        if (n.isEmpty()) {
          return Optional.of("Frame number must be 1..10, got '" + s.trim() + "'");
        }
        cursor[kind.ordinal()] = n.get() - 1;
        row = 0;
        return Optional.empty();
      });
      case F4 -> moveTo(p, m);
      case F5 -> record(p, m);
      case ENTER -> edit(p, null);
      default -> {
        if (k.keypadChar().isPresent()) {
          edit(p, String.valueOf(k.keypadChar().get()));
        }
      }
    }
  }

  @Override
  public void text(Pendant p, String s) {
    if (detail) {
      edit(p, s);
    } else {
      p.message("Open DETAIL (F2) to edit a frame");
    }
  }

  private void edit(Pendant p, String typed) {
    int n = number();
    FrameKind fk = kind;
    if (row == 0) {
      p.entryOrTyped(word() + " Frame " + n + " comment:", typed, p.control().frameComment(fk, n), true, c -> {
        p.control().setFrameComment(fk, n, c.trim());
        return Optional.empty();
      });
      return;
    }
    if (!method().pointNames().isEmpty()) {
      p.message("Record points with SHIFT+F5 RECORD; MOVE_TO with SHIFT+F4");
      return;
    }
    int j = row;
    String field = TpLine.frameWord(fk) + "[" + n + "] " + ELEMENT_NAMES[j - 1];
    p.entryOrTyped("Enter value:", typed, "", false, s -> {
      double v;
      try {
        v = j <= 3 ? NumberEntry.coordinateMm(field, s) : NumberEntry.angleDeg(field, s);
      } catch (ExprText.BadText e) {
        return Optional.of(e.getMessage());
      }
      p.control().setFrame(fk, n, p.control().frame(fk, n).withElement(j, v));
      return Optional.empty();
    });
  }

  private void record(Pendant p, TeachMethod m) {
    if (!p.shift()) {
      p.message("RECORD: hold SHIFT and press F5");
      return;
    }
    if (m.pointNames().isEmpty() || row < 1) {
      p.message("Move the cursor to a point to record it");
      return;
    }
    Position.Joint[] pts = points();
    pts[row - 1] = p.control().currentJoints();
    p.message(m.pointNames().get(row - 1) + " recorded");
    if (Arrays.stream(pts).allMatch(x -> x != null)) {
      TeachResult r = p.control().teachFrame(kind, number(), m, List.of(pts));
      switch (r) {
        case TeachResult.Taught ok -> {
          Position.Cartesian f = ok.frame();
          results.put(key(), String.format(Locale.ROOT, "Taught: X %.1f Y %.1f Z %.1f W %.1f P %.1f R %.1f %s", f.xMm(),
              f.yMm(), f.zMm(), f.wDeg(), f.pDeg(), f.rDeg(), ok.detail()));
          p.message(word() + " Frame " + number() + " taught");
        }
        case TeachResult.Failed no -> {
          results.put(key(), "Not taught: " + no.reason());
          p.message("Frame not taught: " + no.reason());
        }
      }
    } else if (row < pts.length) {
      row++;
    }
  }

  private void moveTo(Pendant p, TeachMethod m) {
    if (!p.shift()) {
      p.message("MOVE_TO: hold SHIFT and press F4");
      return;
    }
    if (m.pointNames().isEmpty() || row < 1 || points()[row - 1] == null) {
      p.message("MOVE_TO: the cursor is not on a recorded point");
      return;
    }
    Result r = p.control().moveTo(points()[row - 1], 0, 0);
    p.message(switch (r) {
      case Result.Ok ok -> ok.message().isEmpty() ? "Moving to " + m.pointNames().get(row - 1) : ok.message();
      case Result.Refused no -> no.reason();
    });
  }
}
