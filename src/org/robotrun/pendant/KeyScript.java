package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.DoubleConsumer;
import org.robotrun.control.RobotControl;

/**
 * A {@code .keys} script: one pendant action per line, for tests, tutorials and graders.
 *
 * <pre>
 * # comment                 (whole line)
 * SHIFT+F1                  SHIFT held around one key press
 * ENTER                     a key press and release (legend or name: F1, I/O, +%, +X/J1, +X, J1+)
 * DOWN *3                   the same key three times
 * TYPE PICK1                typed text (the rest of the line, as written)
 * HOLD SHIFT                key down (stays down)
 * RELEASE SHIFT             key up
 * CLICK +X                  an on-screen click: latches a jog key on (a second CLICK turns it off)
 * HOLD DEADMAN              the DEADMAN gripped (RELEASE DEADMAN lets go: SRVO-003 if the TP is on)
 * TP ON / TP OFF            the pendant's TP ENABLE switch
 * MODE T1 / T2 / AUTO       the operator panel's mode switch
 * ESTOP / ESTOP PANEL       the pendant's / the operator panel's E-stop pressed
 * RELEASE ESTOP             both E-stops twisted out (RESET then clears the alarm)
 * CYCLE START               the operator panel's CYCLE START (AUTO, TP off)
 * UI[6] ON / DI[3] OFF      a PLC input set (the PLC panel): UOP inputs UI[1..18] and DI[]
 * ROBOT 2 / ROBOT robot2    drive another robot of the cell (by number from 1 or by name): its
 *                           own pendant, as the robot selector in the window
 * WAIT 2.5                  2.5 s of simulated time
 * SHOW                      print the LCD
 * </pre>
 *
 * A script starts like a student picking up the pendant of a cold-started controller: TP ON,
 * DEADMAN released, mode T1 (the override's cold start, 10%, is set by whoever starts the
 * controller: {@code robotrun pendant}, the window). A script is parsed whole before it runs, so a malformed line stops it before any key is
 * pressed.
 */
public final class KeyScript {
  /** One action. */
  public sealed interface Step {
    /** Source line (1-based) for messages. */
    int line();

    /** Key press and release, with SHIFT held around it when {@code shift}. */
    record Tap(int line, Key key, boolean shift, int times) implements Step {}

    /** Key down. */
    record Press(int line, Key key) implements Step {}

    /** Key up. */
    record Release(int line, Key key) implements Step {}

    /** An on-screen click (latched jog). */
    record Click(int line, Key key) implements Step {}

    /** Typed text. */
    record Type(int line, String text) implements Step {}

    /** Simulated seconds. */
    record Wait(int line, double seconds) implements Step {}

    /** Print the LCD. */
    record Show(int line) implements Step {}

    /** TP ENABLE on or off. */
    record TpSwitch(int line, boolean on) implements Step {}

    /** The mode switch. */
    record Mode(int line, RobotControl.Mode mode) implements Step {}

    /** An E-stop pressed (the pendant's, or the operator panel's). */
    record Estop(int line, boolean fromPendant) implements Step {}

    /** Both E-stops released. */
    record ReleaseEstop(int line) implements Step {}

    /** CYCLE START on the operator panel. */
    record CycleStart(int line) implements Step {}

    /** A PLC input set by hand: {@code UI[6] ON}, {@code DI[3] OFF} (the PLC panel). */
    record Input(int line, org.robotrun.program.IoKind kind, int index, boolean on) implements Step {}

    /** Switch to another robot's pendant: a number from 1 or a robot name. */
    record SelectRobot(int line, String robot) implements Step {}
  }

  /** A parse failure: where and what. */
  public record Malformed(String file, int line, String message) {
    /** {@code file:line: message}. */
    public String display() {
      return file + ":" + line + ": " + message;
    }
  }

  /** Largest key script read, in bytes (a script is typed by hand or generated; 1 MiB is plenty). */
  public static final long MAX_FILE_BYTES = 1L << 20;

  /** Longest simulated time one WAIT may ask for, in seconds. */
  public static final double MAX_WAIT_SEC = 3600;

  /**
   * Longest simulated time a whole script may ask for, in seconds (the sum of its WAITs): each
   * WAIT is bounded, and so is the sum, so a script cannot keep a grader busy for days.
   */
  public static final double MAX_TOTAL_WAIT_SEC = 4 * 3600;

  private final List<Step> steps;
  /** {@code UI[6] ON}: an input the PLC drives, set by hand. */
  /** An input line: an address ({@link org.robotrun.program.IoAddress}, UI or DI) and ON or OFF. */
  private static final java.util.regex.Pattern INPUT = java.util.regex.Pattern.compile("(.+?)\\s+(ON|OFF)");

  private KeyScript(List<Step> steps) {
    this.steps = List.copyOf(steps);
  }

  /** The steps in order. */
  public List<Step> steps() {
    return steps;
  }

  /** Parses script lines; {@code file} names the source in messages. */
  public static Parsed parse(String file, List<String> lines) {
    Objects.requireNonNull(file, "file");
    List<Step> steps = new ArrayList<>();
    double totalWaitSec = 0;
    for (int i = 0; i < lines.size(); i++) {
      int n = i + 1;
      String raw = lines.get(i);
      if (i == 0 && raw.startsWith("\uFEFF")) {
        raw = raw.substring(1);  // a UTF-8 byte order mark (Windows editors write one)
      }
      // Plain text only: a NUL or another control character (a binary file, a bad encoding) is
      // named, never stripped and run as if it were not there (issue 26).
      for (int c = 0; c < raw.length(); c++) {
        char ch = raw.charAt(c);
        if (ch != '\t' && (Character.isISOControl(ch) || ch == '\uFEFF')) {
          return bad(file, n, String.format(Locale.ROOT, "control character U+%04X at column %d: a key script is plain "
              + "text (UTF-8)", (int) ch, c + 1));
        }
      }
      String t = raw.strip();
      if (t.isEmpty() || t.startsWith("#")) {
        continue;
      }
      java.util.regex.Matcher io = INPUT.matcher(t.toUpperCase(Locale.ROOT));
      Optional<org.robotrun.program.IoAddress> address = io.matches()
          ? org.robotrun.program.IoAddress.parse(io.group(1)).filter(a -> a.kind().equals("UI") || a.kind().equals("DI"))
          : Optional.empty();
      if (address.isPresent()) {
        org.robotrun.program.IoKind kind = org.robotrun.program.IoKind.valueOf(address.get().kind());
        int index = address.get().index();
        int size = org.robotrun.program.IoRanges.DEFAULT.size(kind);
        if (index < 1 || index > size) {
          return bad(file, n, kind + "[" + index + "]: index out of range (expected 1.." + size + ")");
        }
        steps.add(new Step.Input(n, kind, index, io.group(2).equals("ON")));
        continue;
      }
      String word = t.split("\\s+", 2)[0].toUpperCase(Locale.ROOT);
      String rest = t.length() > word.length() ? t.substring(word.length()).strip() : "";
      switch (word) {
        case "SHOW" -> {
          if (!rest.isEmpty()) {
            return bad(file, n, "SHOW takes nothing after it");
          }
          steps.add(new Step.Show(n));
        }
        case "TYPE" -> {
          // the text as written after "TYPE ", inner spaces kept
          String text = raw.stripLeading().substring(4);
          text = text.startsWith(" ") ? text.substring(1) : text;
          if (text.isBlank()) {
            return bad(file, n, "TYPE needs the text to type");
          }
          steps.add(new Step.Type(n, text.stripTrailing()));
        }
        case "WAIT" -> {
          // a plain decimal (docs/pendant.md): "2.5", not "1e3", "+2" or other scripts' digits
          java.util.OptionalDouble v = rest.matches("-?([0-9]{1,9}(\\.[0-9]{0,9})?|\\.[0-9]{1,9})")
              ? org.robotrun.math.DecimalText.parse(rest) : java.util.OptionalDouble.empty();
          if (v.isEmpty()) {
            return bad(file, n, "WAIT needs seconds (e.g. WAIT 2.5), got '" + rest + "'");
          }
          double s = v.getAsDouble();
          if (!(s >= 0) || s > MAX_WAIT_SEC) {
            return bad(file, n, "WAIT seconds must be 0..3600, got " + rest);
          }
          totalWaitSec += s;
          if (totalWaitSec > MAX_TOTAL_WAIT_SEC) {
            return bad(file, n, "the WAITs up to here add up to more than " + (long) MAX_TOTAL_WAIT_SEC
                + " s of simulated time, the limit for one script");
          }
          steps.add(new Step.Wait(n, s));
        }
        case "TP" -> {
          switch (rest.toUpperCase(Locale.ROOT)) {
            case "ON" -> steps.add(new Step.TpSwitch(n, true));
            case "OFF" -> steps.add(new Step.TpSwitch(n, false));
            default -> {
              return bad(file, n, "TP needs ON or OFF, got '" + rest + "'");
            }
          }
        }
        case "MODE" -> {
          try {
            steps.add(new Step.Mode(n, RobotControl.Mode.valueOf(rest.toUpperCase(Locale.ROOT))));
          } catch (IllegalArgumentException e) {
            return bad(file, n, "MODE needs T1, T2 or AUTO, got '" + rest + "'");
          }
        }
        case "ESTOP" -> {
          switch (rest.toUpperCase(Locale.ROOT)) {
            case "", "TP", "PENDANT" -> steps.add(new Step.Estop(n, true));
            case "PANEL" -> steps.add(new Step.Estop(n, false));
            default -> {
              return bad(file, n, "ESTOP takes nothing (the pendant's) or PANEL (the operator panel's), got '" + rest + "'");
            }
          }
        }
        case "CYCLE" -> {
          if (!rest.equalsIgnoreCase("START")) {
            return bad(file, n, "did you mean CYCLE START? got '" + t + "'");
          }
          steps.add(new Step.CycleStart(n));
        }
        case "ROBOT" -> {
          if (rest.isEmpty() || rest.contains(" ")) {
            return bad(file, n, "ROBOT needs a robot's number (from 1) or name, e.g. ROBOT 2, got '" + rest + "'");
          }
          steps.add(new Step.SelectRobot(n, rest));
        }
        case "CLICK" -> {
          Optional<Key> k = Key.parse(rest);
          if (k.isEmpty()) {
            return bad(file, n, "CLICK needs a key name, got '" + rest + "'");
          }
          steps.add(new Step.Click(n, k.get()));
        }
        case "HOLD", "RELEASE" -> {
          if (rest.isEmpty()) {
            // HOLD alone is the HOLD key
            if (word.equals("HOLD")) {
              steps.add(new Step.Tap(n, Key.HOLD, false, 1));
              continue;
            }
            return bad(file, n, "RELEASE needs a key name");
          }
          if (word.equals("RELEASE") && rest.equalsIgnoreCase("ESTOP")) {
            steps.add(new Step.ReleaseEstop(n));
            continue;
          }
          Optional<Key> k = Key.parse(rest);
          if (k.isEmpty()) {
            return bad(file, n, "unknown key '" + rest + "'");
          }
          steps.add(word.equals("HOLD") ? new Step.Press(n, k.get()) : new Step.Release(n, k.get()));
        }
        default -> {
          String keyText = t;
          int times = 1;
          int star = t.lastIndexOf('*');
          if (star > 0) {
            String count = t.substring(star + 1).strip();
            if (!count.matches("[0-9]{1,9}")) {
              return bad(file, n, "repeat count after * must be a whole number");
            }
            times = Integer.parseInt(count);
            if (times < 1 || times > 1000) {
              return bad(file, n, "repeat count must be 1..1000");
            }
            keyText = t.substring(0, star).strip();
          }
          boolean shift = false;
          Optional<Key> k = Key.parse(keyText);
          if (k.isEmpty() && keyText.toUpperCase(Locale.ROOT).startsWith("SHIFT+")) {
            shift = true;
            k = Key.parse(keyText.substring(6));
          }
          if (k.isEmpty()) {
            return bad(file, n, "unknown key or command '" + keyText + "' (keys: F1..F5, ENTER, SHIFT+FWD, +X/J1...;"
                + " commands: TYPE, HOLD, RELEASE, CLICK, TP, MODE, ESTOP, CYCLE START, ROBOT, UI[i] ON/OFF, DI[i] ON/OFF, "
                + "WAIT, SHOW)");
          }
          steps.add(new Step.Tap(n, k.get(), shift, times));
        }
      }
    }
    return new Parsed.Ok(new KeyScript(steps));
  }

  private static Parsed bad(String file, int line, String message) {
    return new Parsed.Bad(new Malformed(file, line, message));
  }

  /** Outcome of {@link #parse}. */
  public sealed interface Parsed {
    /** A script ready to run. */
    record Ok(KeyScript script) implements Parsed {}

    /** The first malformed line. */
    record Bad(Malformed error) implements Parsed {}
  }

  /**
   * Runs the script on {@code pendant}; {@code clock} advances the cell's simulated time by the
   * seconds it is given (a WAIT); every SHOW hands {@code show} a header line and the LCD text.
   */
  public void run(Pendant pendant, DoubleConsumer clock, Consumer<String> show) {
    run(pendant, clock, show, () -> false);
  }

  /**
   * Runs the script as {@link #run(Pendant, DoubleConsumer, Consumer)} does, asking {@code stop} between steps
   * (and every simulated second of a WAIT); when it answers true the script ends there and this
   * returns the line it stopped before, or 0 when the script ran to its end.
   */
  public int run(Pendant pendant, DoubleConsumer clock, Consumer<String> show, java.util.function.BooleanSupplier stop) {
    return run(List.of(pendant), List.of("robot1"), clock, show, stop);
  }

  /**
   * The first ROBOT line naming a robot that is not among {@code robots} (names in cell order),
   * if any: checked before a script runs, so it stops before any key is pressed.
   */
  public Optional<Malformed> unknownRobot(String file, List<String> robots) {
    for (Step s : steps) {
      if (s instanceof Step.SelectRobot r && robotIndex(r.robot(), robots) < 0) {
        return Optional.of(new Malformed(file, r.line(), "no robot " + r.robot() + " in this cell (robots: 1.."
            + robots.size() + ": " + String.join(", ", robots) + ")"));
      }
    }
    return Optional.empty();
  }

  /**
   * The first {@code UI[i]}/{@code DI[i]} line whose index the robot it drives (the one the ROBOT lines
   * before it select) does not have, checked before any key is pressed; the parse checked only the
   * controller's default sizes. Call after {@link #unknownRobot} found nothing.
   */
  public Optional<Malformed> inputOutOfRange(String file, List<String> robots, List<Pendant> pendants) {
    int k = 0;
    for (Step s : steps) {
      if (s instanceof Step.SelectRobot r) {
        k = Math.max(0, robotIndex(r.robot(), robots));
      } else if (s instanceof Step.Input in) {
        int size = pendants.get(k).control().registers().ioSize(in.kind());
        if (in.index() > size) {
          return Optional.of(new Malformed(file, in.line(), in.kind() + "[" + in.index() + "]: index out of range (expected 1.."
              + size + (robots.size() > 1 ? " on " + robots.get(k) : " on this robot") + ")"));
        }
      }
    }
    return Optional.empty();
  }

  /** Slice of simulated time between two looks of the pendant at the executing line. */
  static final double FOLLOW_SLICE_SEC = 0.02;

  /** Advances the cell by {@code dtSec}; the EDIT cursor follows the executing line as it goes. */
  public static void advance(Pendant pendant, DoubleConsumer clock, double dtSec) {
    double left = dtSec;
    while (left > 1e-12) {
      double dt = Math.min(FOLLOW_SLICE_SEC, left);
      clock.accept(dt);
      left -= dt;
      pendant.follow();
    }
  }

  private static int robotIndex(String robot, List<String> robots) {
    for (int i = 0; i < robots.size(); i++) {
      if (robots.get(i).equals(robot)) {
        return i;
      }
    }
    if (robot.matches("\\d{1,3}")) {
      int k = Integer.parseInt(robot);
      return k >= 1 && k <= robots.size() ? k - 1 : -1;
    }
    return -1;
  }

  /**
   * Runs the script on a cell of several robots, each with its own pendant (in cell order, named
   * {@code robots}); it starts on the first, and {@code ROBOT} switches. Time (WAIT) advances the
   * whole cell through {@code clock} whichever pendant is in hand, in slices of
   * {@value #FOLLOW_SLICE_SEC} s after each of which the pendant in hand follows the controller. With several robots the SHOW header names the robot.
   *
   * @throws IllegalArgumentException if a ROBOT line names no robot of the cell (see {@link #unknownRobot})
   */
  public int run(List<Pendant> pendants, List<String> robots, DoubleConsumer clock, Consumer<String> show,
      java.util.function.BooleanSupplier stop) {
    if (pendants.size() != robots.size() || pendants.isEmpty()) {
      throw new IllegalArgumentException("one pendant per robot: " + pendants.size() + " pendants, " + robots.size() + " robots");
    }
    Pendant pendant = pendants.get(0);
    String robotName = robots.get(0);
    double timeSec = 0;
    for (Step s : steps) {
      if (stop.getAsBoolean()) {
        return s.line();
      }
      switch (s) {
        case Step.Tap t -> {
          for (int i = 0; i < t.times(); i++) {
            if (t.shift()) {
              pendant.press(Key.SHIFT);
            }
            pendant.tap(t.key());
            if (t.shift()) {
              pendant.release(Key.SHIFT);
            }
          }
        }
        case Step.Press p -> pendant.press(p.key());
        case Step.Release r -> pendant.release(r.key());
        case Step.Click c -> pendant.click(c.key());
        case Step.Type t -> pendant.type(t.text());
        case Step.Wait w -> {
          double left = w.seconds();
          while (left > 0) {
            if (stop.getAsBoolean()) {
              return w.line();
            }
            double chunk = Math.min(1.0, left);
            advance(pendant, clock, chunk);
            left -= chunk;
          }
          timeSec += w.seconds();
        }
        case Step.TpSwitch sw -> pendant.setTpEnabled(sw.on());
        case Step.Mode m -> pendant.setMode(m.mode());
        case Step.Estop e -> pendant.emergencyStop(e.fromPendant());
        case Step.ReleaseEstop r -> pendant.releaseEmergencyStop();
        case Step.CycleStart c -> pendant.cycleStart();
        case Step.Input in -> pendant.control().registers().setBit(in.kind(), in.index(), in.on());
        case Step.SelectRobot r -> {
          int k = robotIndex(r.robot(), robots);
          if (k < 0) {
            throw new IllegalArgumentException("line " + r.line() + ": no robot " + r.robot() + " in this cell");
          }
          pendant = pendants.get(k);
          robotName = robots.get(k);
        }
        case Step.Show sh -> show.accept(String.format(Locale.ROOT, "-- SHOW (line %d, t=%.3f s%s) --%n%s", sh.line(),
            timeSec, pendants.size() > 1 ? ", " + robotName : "", pendant.render()));
      }
    }
    return 0;
  }
}
