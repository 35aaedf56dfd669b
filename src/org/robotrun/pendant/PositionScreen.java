package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.CommentTable;
import org.robotrun.control.RobotControl.Conversion;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * Position detail: a program's P[n] or a position register PR[n] in Cartesian (X..R, CONFIG)
 * or joint (J1..J6) form. The cursor sits on the comment or a component; typed or keypad
 * numbers replace it (direct entry). [REPRE] converts between the forms through the
 * controller's kinematics; RECORD (SHIFT+F3) stores the current position.
 */
final class PositionScreen implements Screen {
  /** Which position is shown. */
  sealed interface Target {
    /** P[number] of program {@code program}. */
    record Local(String program, int number) implements Target {}

    /** PR[number]. */
    record Register(int number) implements Target {}
  }

  private final Target target;
  /** 0 = comment, 1..6 = components, 7 = CONFIG (Cartesian only). */
  private int row = 1;

  private PositionScreen(Target target) {
    this.target = target;
  }

  static void openLocal(Pendant p, String program, int number) {
    p.show(new PositionScreen(new Target.Local(program, number)));
  }

  static void openRegister(Pendant p, int number) {
    p.show(new PositionScreen(new Target.Register(number)));
  }

  private Optional<Position> position(Pendant p) {
    return switch (target) {
      case Target.Local l -> p.control().program(l.program()).flatMap(pr -> pr.position(l.number()))
          .map(LocalPosition::position);
      case Target.Register r -> Optional.of(p.control().registers().position(r.number()));
    };
  }

  private int[] frames(Pendant p) {
    return switch (target) {
      case Target.Local l -> p.control().program(l.program()).flatMap(pr -> pr.position(l.number()))
          .map(lp -> new int[] {lp.userFrame(), lp.toolFrame()}).orElse(new int[] {0, 0});
      case Target.Register r -> new int[] {p.control().activeFrame(FrameKind.USER), p.control().activeFrame(FrameKind.TOOL)};
    };
  }

  private String comment(Pendant p) {
    return switch (target) {
      case Target.Local l -> p.control().program(l.program()).flatMap(pr -> pr.position(l.number()))
          .map(LocalPosition::comment).orElse("");
      case Target.Register r -> p.control().comment(CommentTable.PR, r.number());
    };
  }

  private String name() {
    return switch (target) {
      case Target.Local l -> "P[" + l.number() + "]";
      case Target.Register r -> "PR[" + r.number() + "]";
    };
  }

  /** Stores a changed position (and comment) where it lives. */
  private void store(Pendant p, Position pos, String comment) {
    switch (target) {
      case Target.Local l -> {
        int[] uf = frames(p);
        p.editProgram(l.program(), pr -> {
          Map<Integer, LocalPosition> m = new LinkedHashMap<>(pr.positions());
          m.put(l.number(), new LocalPosition(l.number(), comment, uf[0], uf[1], pos));
          return pr.withBody(pr.lines(), m);
        });
      }
      case Target.Register r -> {
        p.control().registers().setPosition(r.number(), pos);
        p.control().setComment(CommentTable.PR, r.number(), comment);
      }
    }
  }

  @Override
  public String title(Pendant p) {
    String owner = target instanceof Target.Local l ? "  (" + l.program() + ")" : "";
    return "POSITION DETAIL " + name() + owner;
  }

  @Override
  public List<String> body(Pendant p) {
    List<String> rows = new ArrayList<>();
    Optional<Position> pos = position(p);
    int[] f = frames(p);
    rows.add(mark(0) + name() + " comment: " + (row == 0 ? "{" + comment(p) + "}" : comment(p)));
    if (pos.isEmpty()) {
      rows.add("  (not recorded)");
      return rows;
    }
    rows.add(String.format(Locale.ROOT, "  UF:%d  UT:%d   %s", f[0], f[1],
        pos.get() instanceof Position.Cartesian c ? "CONF: " + config(c.config()) : "JOINT"));
    String[] names = pos.get() instanceof Position.Cartesian ? CARTESIAN_NAMES
        : jointLabels(p.control().jointNames()).toArray(String[]::new);
    String[] units = pos.get() instanceof Position.Cartesian ? new String[] {"mm", "mm", "mm", "deg", "deg", "deg"}
        : new String[] {"deg", "deg", "deg", "deg", "deg", "deg"};
    for (int j = 1; j <= 6; j++) {
      String v = String.format(Locale.ROOT, "%10.3f", pos.get().element(j));
      rows.add(mark(j) + String.format(Locale.ROOT, " %-2s %s %s", names[j - 1], row == j ? "{" + v + "}" : v, units[j - 1]));
    }
    if (pos.get() instanceof Position.Cartesian c) {
      String cf = config(c.config());
      rows.add(mark(7) + " CONFIG: " + (row == 7 ? "{" + cf + "}" : cf));
    }
    return rows;
  }

  private String mark(int r) {
    return row == r ? ">" : " ";
  }

  static String config(Config c) {
    return (c.flip() ? "F" : "N") + " " + (c.up() ? "U" : "D") + " " + (c.top() ? "T" : "B") + ", " + c.turn1() + ", "
        + c.turn2() + ", " + c.turn3();
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("", "", target instanceof Target.Register ? "RECORD" : "", "DONE", "[REPRE]");
  }

  @Override
  public void key(Pendant p, Key k) {
    Optional<Position> pos = position(p);
    int last = pos.isPresent() && pos.get() instanceof Position.Cartesian ? 7 : 6;
    switch (k) {
      case UP -> row = Math.max(0, row - 1);
      case DOWN -> row = Math.min(last, row + 1);
      case F4 -> p.prevScreen();
      case F3 -> {
        if (!(target instanceof Target.Register)) {
          p.message("Local positions are recorded with TOUCHUP on the EDIT screen");
        } else if (!p.shift()) {
          p.message("RECORD: hold SHIFT and press F3");
        } else {
          record(p, pos);
        }
      }
      case F5 -> p.choose("Representation", List.of("Cartesian", "Joint"), i -> repre(p, i == 0));
      case ENTER -> edit(p, null);
      default -> {
        if (k.keypadChar().isPresent()) {
          edit(p, String.valueOf(k.keypadChar().get()));
        } else {
          p.message("POSITION: UP/DOWN, type a value, ENTER; F4 DONE");
        }
      }
    }
  }

  @Override
  public void text(Pendant p, String s) {
    edit(p, s);
  }

  private void record(Pendant p, Optional<Position> pos) {
    int uf = p.control().activeFrame(FrameKind.USER);
    int ut = p.control().activeFrame(FrameKind.TOOL);
    Position now = pos.isPresent() && pos.get() instanceof Position.Joint ? p.control().currentJoints()
        : p.control().currentPose(uf, ut);
    store(p, now, comment(p));
    p.message(name() + " recorded");
  }

  private void edit(Pendant p, String typed) {
    Optional<Position> pos = position(p);
    if (row == 0) {
      p.entryOrTyped(name() + " comment:", typed, comment(p), true, c -> {
        store(p, pos.orElse(Position.Cartesian.ZERO), c.trim());
        return Optional.empty();
      });
      return;
    }
    if (pos.isEmpty()) {
      p.message(name() + " is not recorded");
      return;
    }
    if (row == 7 && pos.get() instanceof Position.Cartesian c) {
      p.entryOrTyped("CONFIG (e.g. N U T, 0, 0, 0):", typed, config(c.config()), true, t -> {
        Optional<Config> cf = parseConfig(t);
        if (cf.isEmpty()) {
          return Optional.of("Bad CONFIG '" + t.trim() + "': expected F|N U|D T|B, t1, t2, t3");
        }
        store(p, new Position.Cartesian(c.xMm(), c.yMm(), c.zMm(), c.wDeg(), c.pDeg(), c.rDeg(), cf.get()), comment(p));
        return Optional.empty();
      });
      return;
    }
    int j = row;
    boolean cartesian = pos.get() instanceof Position.Cartesian;
    String field = name() + " " + (cartesian ? CARTESIAN_NAMES[j - 1] : jointLabels(p.control().jointNames()).get(j - 1));
    p.entryOrTyped("Enter value:", typed, "", false, t -> {
      double v;
      try {
        v = cartesian && j <= 3 ? NumberEntry.coordinateMm(field, t) : NumberEntry.angleDeg(field, t);
      } catch (ExprText.BadText e) {
        return Optional.of(e.getMessage());
      }
      store(p, position(p).orElseThrow().withElement(j, v), comment(p));
      return Optional.empty();
    });
  }

  private static final String[] CARTESIAN_NAMES = {"X", "Y", "Z", "W", "P", "R"};
  /** Longest joint label the pendant shows; a longer name from a robot file is cut with "~". */
  static final int MAX_JOINT_LABEL = 20;

  /** The pendant's joint labels: the robot file's names, each cut to {@link #MAX_JOINT_LABEL}. */
  static List<String> jointLabels(List<String> names) {
    List<String> out = new ArrayList<>();
    for (int i = 0; i < 6; i++) {
      String n = i < names.size() && !names.get(i).isBlank() ? names.get(i).replaceAll("[^\\x21-\\x7e]", "?") : "J" + (i + 1);
      out.add(n.length() > MAX_JOINT_LABEL ? n.substring(0, MAX_JOINT_LABEL - 1) + "~" : n);
    }
    return out;
  }

  static Optional<Config> parseConfig(String text) {
    String[] parts = text.trim().toUpperCase(Locale.ROOT).split("\\s*,\\s*");
    if (parts.length != 4) {
      return Optional.empty();
    }
    String[] letters = parts[0].trim().split("\\s+");
    if (letters.length != 3 || !letters[0].matches("[FN]") || !letters[1].matches("[UD]") || !letters[2].matches("[TB]")) {
      return Optional.empty();
    }
    try {
      return Optional.of(new Config(letters[0].equals("F"), letters[1].equals("U"), letters[2].equals("T"),
          Integer.parseInt(parts[1].trim()), Integer.parseInt(parts[2].trim()), Integer.parseInt(parts[3].trim())));
    } catch (NumberFormatException e) {
      return Optional.empty();
    }
  }

  private void repre(Pendant p, boolean cartesian) {
    Optional<Position> pos = position(p);
    if (pos.isEmpty()) {
      p.message(name() + " is not recorded");
      return;
    }
    int[] f = frames(p);
    switch (pos.get()) {
      case Position.Cartesian c -> {
        if (cartesian) {
          p.message("Already Cartesian");
          return;
        }
        switch (p.control().toJoints(c, f[0], f[1])) {
          case Conversion.Ok<Position.Joint> ok -> {
            store(p, ok.value(), comment(p));
            p.message(name() + " is now in joint form");
          }
          case Conversion.Failed<Position.Joint> no -> p.message("Cannot convert: " + no.reason());
        }
      }
      case Position.Joint j -> {
        if (!cartesian) {
          p.message("Already joint");
          return;
        }
        store(p, p.control().toCartesian(j, f[0], f[1]), comment(p));
        p.message(name() + " is now in Cartesian form");
      }
    }
    row = Math.min(row, 6);
  }
}
