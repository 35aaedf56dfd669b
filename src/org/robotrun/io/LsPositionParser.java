package org.robotrun.io;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robotrun.program.FanucFormat;
import org.robotrun.program.TpLexer;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;
import org.robotrun.program.TpToken;
import org.robotrun.program.TpTokenCursor;
import org.robotrun.program.TpToken.Kind;
import org.robotrun.math.PoseLimits;
import org.robotrun.program.Config;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Position;

/**
 * Reads the /POS section: blocks {@code P[n:"comment"]{ GP1: UF : u, UT : t, CONFIG : '...',
 * X = ... mm, ... };} in Cartesian or joint form. A bad block is reported and skipped up to its
 * closing {@code };} so the following blocks are still read; a block that is never closed is
 * reported on its first line.
 */
final class LsPositionParser extends TpTokenCursor {

  private static final String[] CARTESIAN = {"X", "Y", "Z", "W", "P", "R"};
  private static final String[] JOINT = {"J1", "J2", "J3", "J4", "J5", "J6"};
  private static final String[] RAIL = {"RX", "RY", "RZ", "RW", "RP", "RR"};

  private final String file;
  private final List<Diagnostic> diagnostics;

  private final java.util.Set<String> warned = new java.util.HashSet<>();
  private java.util.Set<Integer> otherGroupsOnly = new java.util.HashSet<>();

  /** Kinds of position block read and kept but not held as a position: kind → index of its diagnostic, and count. */
  private final Map<String, int[]> keptSeen = new HashMap<>();

  /** Reports a block kept but not simulated, once per kind with a count of the others. */
  private void keptNotSimulated(TpToken at, String what) {
    String base = "not supported: " + what + " (kept in the file, not moved to: a motion to it alarms)";
    int[] seen = keptSeen.get(what);
    if (seen == null) {
      keptSeen.put(what, new int[] {diagnostics.size(), 0});
      diagnostics.add(Diagnostic.of(file, at.line(), at.column(), Diagnostic.Severity.ERROR,
          Diagnostic.Kind.UNSUPPORTED, base));
    } else {
      seen[1]++;
      Diagnostic d = diagnostics.get(seen[0]);
      diagnostics.set(seen[0], Diagnostic.of(d.file(), d.line(), d.column(), d.severity(), d.kind(),
          base + " (and " + seen[1] + " more position" + (seen[1] == 1 ? ")" : "s)")));
    }
  }

  private void warnOnce(TpToken at, String message) {
    if (warned.add(message)) {
      diagnostics.add(Diagnostic.of(file, at.line(), at.column(), Diagnostic.Severity.WARNING,
          Diagnostic.Kind.UNSUPPORTED, message));
    }
  }

  private LsPositionParser(String file, List<Diagnostic> diagnostics) {
    this.file = file;
    this.diagnostics = diagnostics;
  }

  /**
   * Parses the section's lines.
   *
   * @param lines the section's lines, without the {@code /POS} header
   * @param firstLine the 1-based file line of {@code lines.get(0)}
   * @param diagnostics where problems are added
   * @return P[n] by number in file order; bad blocks are left out (and reported)
   */
  static Map<Integer, LocalPosition> parse(String file, List<String> lines, int firstLine, List<Diagnostic> diagnostics) {
    return parse(file, lines, firstLine, diagnostics, new java.util.HashSet<>());
  }

  /** As {@link #parse(String, List, int, List)}; adds to {@code otherGroupsOnly} the P[n] that hold no group-1 data. */
  static Map<Integer, LocalPosition> parse(String file, List<String> lines, int firstLine, List<Diagnostic> diagnostics,
      java.util.Set<Integer> otherGroupsOnly) {
    LsPositionParser p = new LsPositionParser(file, diagnostics);
    p.otherGroupsOnly = otherGroupsOnly;
    for (int i = 0; i < lines.size(); i++) {
      List<TpToken> t = TpLexer.tokenize(lines.get(i), firstLine + i, 1, false);
      p.tokens.addAll(t.subList(0, t.size() - 1));
    }
    int endLine = firstLine + Math.max(0, lines.size() - 1);
    p.tokens.add(new TpToken(Kind.EOL, "", endLine, 1));
    return p.blocks();
  }

  private Map<Integer, LocalPosition> blocks() {
    Map<Integer, LocalPosition> out = new LinkedHashMap<>();
    Map<Integer, Integer> firstLineOf = new HashMap<>();
    while (!peek().is(Kind.EOL)) {
      TpToken start = peek();
      try {
        LocalPosition lp = block();
        if (lp == null) {
          continue;
        }
        Integer earlier = firstLineOf.putIfAbsent(lp.number(), start.line());
        if (earlier != null) {
          diagnostics.add(Diagnostic.error(file, start.line(),
              "P[" + lp.number() + "] is defined twice in /POS (first on line " + earlier + ")"));
        } else {
          out.put(lp.number(), lp);
        }
      } catch (TpSyntaxError e) {
        diagnostics.add(Diagnostic.error(file, e.line(), e.getMessage()));
        skipPastBlock(start);
      }
    }
    return out;
  }

  /** After an error: skip to just after the next {@code };}, or to the next {@code P[} block start. */
  private void skipPastBlock(TpToken start) {
    if (peek() == start && !peek().is(Kind.EOL)) {
      next();
    }
    while (!peek().is(Kind.EOL)) {
      TpToken t = peek();
      if (t.is(Kind.RBRACE) && peek(1).is(Kind.SEMICOLON)) {
        next();
        next();
        return;
      }
      if (t.isWord("P") && peek(1).is(Kind.LBRACKET) && t.column() == 1) {
        return;
      }
      next();
    }
  }

  private LocalPosition block() {
    TpToken start = peek();
    if (!start.isWord("P") || !peek(1).is(Kind.LBRACKET)) {
      throw error(start, "expected a position block 'P[n:\"comment\"]{', found " + start.describe());
    }
    next();
    next();
    TpToken num = expect(Kind.NUMBER, "the position number in P[n]");
    int number = parseInt(num);
    if (number < 1) {
      throw error(num, "P[" + number + "]: position numbers start at 1");
    }
    String where = "P[" + number + "]";
    String comment = "";
    if (peek().is(Kind.COLON)) {
      next();
      if (peek().is(Kind.ITEM_COMMENT)) {
        comment = unquote(next().text().strip());
      }
    }
    expect(Kind.RBRACKET, "']' closing " + where);
    expect(Kind.LBRACE, "'{' after " + where);

    Map<String, Double> values = new LinkedHashMap<>();
    // Set when the block holds a form RobotRun reads but cannot hold as a position of its arm.
    String kept = null;
    boolean uninitialised = false;
    Integer uf = null;
    Integer ut = null;
    Config config = null;
    boolean sawGroup = false;
    while (true) {
      TpToken t = peek();
      if (t.is(Kind.EOL)) {
        throw error(start, where + " is not closed: expected '};' before the end of the /POS section");
      }
      if (t.is(Kind.RBRACE)) {
        next();
        expect(Kind.SEMICOLON, "';' after the '}' closing " + where);
        break;
      }
      if (t.is(Kind.COMMA)) {
        next();
        continue;
      }
      if (!t.is(Kind.WORD)) {
        throw error(t, where + ": expected a field (GP1:, UF, UT, CONFIG, X..R or J1..J6) or '};', found " + t.describe());
      }
      if (t.isWord("P") && peek(1).is(Kind.LBRACKET) && t.column() == 1) {
        throw error(start, where + " is not closed: expected '};' before the next block on line " + t.line());
      }
      next();
      String key = t.text().toUpperCase(Locale.ROOT);
      if (key.startsWith("GP")) {
        expect(Kind.COLON, "':' after " + t.text());
        if (!key.equals("GP1")) {
          // Another motion group (a positioner, a second arm): kept in the file, not moved.
          warnOnce(t, "not supported: motion group " + key + " (RobotRun moves group 1; the others are kept, not moved)");
          while (!peek().is(Kind.EOL) && !peek().is(Kind.RBRACE)
              && !(peek().is(Kind.WORD) && peek().text().toUpperCase(Locale.ROOT).startsWith("GP") && peek(1).is(Kind.COLON))) {
            next();
          }
          continue;
        }
        if (sawGroup) {
          throw error(t, where + ": GP1 appears twice");
        }
        sawGroup = true;
        continue;
      }
      if (!sawGroup) {
        throw error(t, where + ": expected 'GP1:' before the position data, found " + t.describe());
      }
      switch (key) {
        case "UF", "UT" -> {
          expect(Kind.COLON, "':' after " + key);
          if (peek().isWord("F")) {
            // UF : F, UT : F: a position never taught (its values are listed as ********)
            next();
            uninitialised = true;
            continue;
          }
          int v = parseInt(expect(Kind.NUMBER, "the frame number after " + key + " :"));
          if (key.equals("UF")) {
            uf = v;
          } else {
            ut = v;
          }
        }
        case "CONFIG" -> {
          expect(Kind.COLON, "':' after CONFIG");
          TpToken s = expect(Kind.STRING, "a quoted configuration like 'N U T, 0, 0, 0' after CONFIG :");
          String arm = s.text().split(",", -1)[0].strip().toUpperCase(Locale.ROOT);
          if (arm.equals("L") || arm.equals("R")) {
            // SCARA: left- or right-handed arm, 'R, 0, 0, 0'
            kept = "a SCARA position (CONFIG 'L' or 'R')";
            continue;
          }
          if (!arm.isEmpty() && arm.matches("[FNUDTB]( [FNUDTB])*") && arm.split(" ").length != 3) {
            // 'N, 0, 0, 0', 'N B, 0, 0, 0': an arm of four or five axes lists fewer configuration letters
            kept = "a position of an arm with other than six axes (CONFIG '" + TpToken.clip(s.text()) + "')";
            continue;
          }
          config = config(s, where);
        }
        default -> {
          if (key.matches("E\\d+")) {
            // An extended axis (a rail, a turntable): read and kept in the file, not moved.
            warnOnce(t, "not supported: extended axes (E1...) (kept, not moved)");
            skipKeptValue(key);
            continue;
          }
          if (key.matches("J([7-9]|[1-9][0-9])")) {
            // J7 = ... deg: a seven-axis arm (or a group listing more joints): kept, not moved
            skipKeptValue(key);
            kept = "a position of an arm with more than six joints (J7 ...)";
            continue;
          }
          if (indexOf(RAIL, key) >= 0) {
            // RX = ... mm, RW = ... deg: a robot with an integrated rail lists its pose this way
            skipKeptValue(key);
            kept = "a position of a robot on an integrated rail (RX .. RR)";
            continue;
          }
          boolean cart = indexOf(CARTESIAN, key) >= 0;
          boolean joint = indexOf(JOINT, key) >= 0;
          if (!cart && !joint) {
            throw error(t, where + ": unknown field '" + TpToken.clip(t.text())
                + "': expected UF, UT, CONFIG, X, Y, Z, W, P, R or J1..J6");
          }
          expect(Kind.EQ, "'=' after " + key);
          if (peek().is(Kind.STAR)) {
            // "X = ********  mm": the controller lists a position never taught this way
            while (peek().is(Kind.STAR)) {
              next();
            }
            if (peek().isWord("mm") || peek().isWord("deg")) {
              next();
            }
            uninitialised = true;
            continue;
          }
          boolean negative = peek().is(Kind.MINUS);
          if (negative) {
            next();
          }
          TpToken n = expect(Kind.NUMBER, "a number after " + key + " =");
          // Held to 0.001 as a controller holds and prints it, so the model writes back as read.
          double v = Double.parseDouble(FanucFormat.positionValue(Double.parseDouble(n.text())).strip());
          String unit = (key.equals("X") || key.equals("Y") || key.equals("Z")) ? "mm" : "deg";
          TpToken u = peek();
          if (!u.isWord(unit)) {
            throw error(u, where + ": expected '" + unit + "' after the value of " + key + ", found " + u.describe());
          }
          next();
          boolean inRange = unit.equals("mm") ? PoseLimits.coordinateOk(v) : PoseLimits.angleOk(v);
          if (!inRange) {
            long max = (long) (unit.equals("mm") ? PoseLimits.MAX_COORDINATE_MM : PoseLimits.MAX_ANGLE_DEG);
            throw error(n, where + ": " + key + " = " + (negative ? "-" : "") + TpToken.clip(n.text()) + " " + unit
                + " is out of range: expected -" + max + ".." + max + " " + unit);
          }
          // -0.000 is read as 0 (the writer prints zero unsigned), so a round trip keeps the model.
          if (values.put(key, negative && v != 0 ? -v : v) != null) {
            throw error(t, where + ": " + key + " appears twice");
          }
        }
      }
    }
    if (uninitialised && kept == null) {
      // Loaded as the controller loads it: the position shows uninitialised; a motion to it alarms.
      diagnostics.add(Diagnostic.of(file, start.line(), start.column(), Diagnostic.Severity.WARNING,
          Diagnostic.Kind.REFERENCE, where + " is uninitialised (never taught): a motion to it alarms"));
      otherGroupsOnly.add(number);
      return null;
    }
    if (kept != null) {
      keptNotSimulated(start, kept);
      otherGroupsOnly.add(number);
      return null;
    }
    if (!sawGroup && uf == null && ut == null && values.isEmpty()) {
      otherGroupsOnly.add(number);
      return null; // only other groups' data: kept in the file, nothing for group 1
    }
    if (uf == null || ut == null) {
      throw error(start, where + ": expected 'UF : n, UT : n' (the frames the position was taught in)");
    }
    return new LocalPosition(number, comment, uf, ut, position(values, config, where, start));
  }

  private Position position(Map<String, Double> v, Config config, String where, TpToken start) {
    boolean anyCart = false;
    boolean anyJoint = false;
    for (String k : v.keySet()) {
      anyCart |= indexOf(CARTESIAN, k) >= 0;
      anyJoint |= indexOf(JOINT, k) >= 0;
    }
    if (anyCart && anyJoint) {
      throw error(start, where + ": mixes Cartesian (X..R) and joint (J1..J6) values; expected one form");
    }
    if (!anyCart && !anyJoint) {
      throw error(start, where + ": has no position: expected X, Y, Z, W, P, R or J1..J6");
    }
    String[] keys = anyCart ? CARTESIAN : JOINT;
    double[] d = new double[6];
    for (int i = 0; i < 6; i++) {
      Double x = v.get(keys[i]);
      if (x == null) {
        throw error(start, where + ": " + keys[i] + " is missing: expected all of " + String.join(", ", keys));
      }
      d[i] = x;
    }
    if (anyJoint) {
      if (config != null) {
        diagnostics.add(Diagnostic.warning(file, start.line(), where + ": CONFIG ignored on a joint position"));
      }
      return new Position.Joint(d[0], d[1], d[2], d[3], d[4], d[5]);
    }
    if (config == null) {
      diagnostics.add(Diagnostic.warning(file, start.line(), where + ": no CONFIG; assuming 'N U T, 0, 0, 0'"));
      config = Config.DEFAULT;
    }
    return new Position.Cartesian(d[0], d[1], d[2], d[3], d[4], d[5], config);
  }

  /** {@code 'N U T, 0, 0, 0'}: flip F|N, elbow U|D, arm T|B, then up to three turn numbers. */
  private Config config(TpToken s, String where) {
    String[] parts = s.text().split(",", -1);
    String[] letters = parts[0].trim().toUpperCase(Locale.ROOT).split("\\s+");
    String expected = where + ": CONFIG '" + TpToken.clip(s.text())
        + "': expected 'F|N U|D T|B, t1, t2, t3' like 'N U T, 0, 0, 0'";
    if (letters.length != 3 || parts.length > 4) {
      throw error(s, expected);
    }
    boolean flip = switch (letters[0]) {
      case "F" -> true;
      case "N" -> false;
      default -> throw error(s, expected);
    };
    boolean up = switch (letters[1]) {
      case "U" -> true;
      case "D" -> false;
      default -> throw error(s, expected);
    };
    boolean top = switch (letters[2]) {
      case "T" -> true;
      case "B" -> false;
      default -> throw error(s, expected);
    };
    int[] turns = new int[3];
    for (int i = 1; i < parts.length; i++) {
      try {
        turns[i - 1] = Integer.parseInt(parts[i].trim());
      } catch (NumberFormatException e) {
        throw error(s, expected);
      }
    }
    return new Config(flip, up, top, turns[0], turns[1], turns[2]);
  }

  private static String unquote(String s) {
    if (s.length() >= 2 && s.startsWith("\"") && s.endsWith("\"")) {
      return s.substring(1, s.length() - 1);
    }
    return s;
  }

  private static int indexOf(String[] a, String k) {
    for (int i = 0; i < a.length; i++) {
      if (a[i].equals(k)) {
        return i;
      }
    }
    return -1;
  }

  private int parseInt(TpToken t) {
    if (t.text().indexOf('.') >= 0) {
      throw error(t, "expected an integer, found " + t.describe());
    }
    try {
      return Integer.parseInt(t.text());
    } catch (NumberFormatException e) {
      throw error(t, "number " + TpToken.clip(t.text()) + " is too large");
    }
  }

  /** Reads {@code = [-]NUMBER [mm|deg]} after a field RobotRun keeps in the file but does not move. */
  private void skipKeptValue(String key) {
    expect(Kind.EQ, "'=' after " + key);
    if (peek().is(Kind.MINUS)) {
      next();
    }
    expect(Kind.NUMBER, "a number after " + key + " =");
    if (peek().isWord("mm") || peek().isWord("deg")) {
      next();
    }
  }
}
