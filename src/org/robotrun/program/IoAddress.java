package org.robotrun.program;

import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * An I/O address as RobotRun's files write it, {@code KIND[i]} ({@code DO[3]}, {@code UI[6]}):
 * the one reader of that form, for the wiring ({@code robot1.DO[10]}), the production setup and
 * key scripts. The kind is upper case here; whether it is a kind the caller accepts, and whether
 * the index is in range, is the caller's to check (with its own message).
 *
 * @param kind the kind's name as written, upper case ("DO", "UI"); not checked against {@link IoKind}
 * @param index the index as written (1-based on the controller; 0 or huge are the caller's to refuse)
 */
public record IoAddress(String kind, int index) {
  private static final Pattern FORM = Pattern.compile("([A-Za-z]+)\\[\\s*(\\d{1,9})\\s*\\]");

  /** {@code KIND[i]}, spaces around the whole and inside the brackets allowed; empty when the text is not of that form. */
  public static Optional<IoAddress> parse(String text) {
    Matcher m = FORM.matcher(text.strip());
    if (!m.matches()) {
      return Optional.empty();
    }
    return Optional.of(new IoAddress(m.group(1).toUpperCase(Locale.ROOT), Integer.parseInt(m.group(2))));
  }

  /**
   * {@code ROBOT.KIND[i]}: the robot is everything before the last dot ahead of the address
   * (so a robot name may hold dots); empty when the text is not of that form.
   */
  public static Optional<Located> parseOnRobot(String text) {
    String t = text.strip();
    int bracket = t.indexOf('[');
    int dot = bracket < 0 ? t.lastIndexOf('.') : t.lastIndexOf('.', bracket);
    if (dot <= 0) {
      return Optional.empty();
    }
    Matcher m = FORM.matcher(t.substring(dot + 1));
    if (!m.matches()) {
      return Optional.empty();
    }
    return Optional.of(new Located(t.substring(0, dot),
        new IoAddress(m.group(1).toUpperCase(Locale.ROOT), Integer.parseInt(m.group(2)))));
  }

  /** An address on a named robot. */
  public record Located(String robot, IoAddress address) {}

  @Override
  public String toString() {
    return kind + "[" + index + "]";
  }
}
