package org.robotrun.program;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * A TP program as an .LS file holds it (immutable).
 *
 * @param name program name: letters, digits and '_', starting with a letter, at most 36 chars
 * @param attributes every /ATTR entry other than COMMENT, in the order read: key to the raw text
 *     between {@code =} and the closing {@code ;} (trimmed), e.g. {@code "OWNER" -> "MNEDITOR"},
 *     {@code "CREATE" -> "DATE 25-01-10  TIME 09:00:00"}; a writer fills in sane defaults for
 *     missing keys
 * @param comment the COMMENT attribute without its quotes ("" when absent)
 * @param lines the /MN lines; line n is {@code lines.get(n - 1)}
 * @param positions the /POS block: P[n] by number, in the order read
 * @param source the text the program was read from, when it was read from a file: the writer
 *     keeps what was not edited as it was. Not part of the program's value: two programs with
 *     the same name, attributes, comment, lines and positions are equal whatever text they came from.
 */
public record Program(String name, Map<String, String> attributes, String comment, List<Instruction> lines,
    Map<Integer, LocalPosition> positions, Optional<ProgramSource> source) {

  /** Longest program name FANUC accepts. */
  public static final int MAX_NAME_LENGTH = 36;

  /** A program not read from a file. */
  public Program(String name, Map<String, String> attributes, String comment, List<Instruction> lines,
      Map<Integer, LocalPosition> positions) {
    this(name, attributes, comment, lines, positions, Optional.empty());
  }

  public Program {
    Objects.requireNonNull(name, "name");
    Objects.requireNonNull(source, "source");
    Objects.requireNonNull(comment, "comment");
    attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
    lines = List.copyOf(lines);
    positions = Collections.unmodifiableMap(new LinkedHashMap<>(positions));
    for (Map.Entry<Integer, LocalPosition> e : positions.entrySet()) {
      if (e.getKey() != e.getValue().number()) {
        throw new IllegalArgumentException("P[" + e.getKey() + "] holds position number " + e.getValue().number());
      }
    }
  }

  /**
   * Whether this program holds motion group 1: its group mask ({@code DEFAULT_GROUP} in /ATTR)
   * starts with 1; a program with no mask has group 1, as a program created on the pendant does.
   */
  public boolean usesMotionGroup() {
    return attributes.getOrDefault("DEFAULT_GROUP", "1,*,*,*,*").strip().startsWith("1");
  }

  /** A program with no attributes, comment or positions (tests, new programs). */
  public static Program of(String name, List<Instruction> lines) {
    return new Program(name, Map.of(), "", lines, Map.of());
  }

  /** A program with lines and local positions. */
  public static Program of(String name, List<Instruction> lines, List<LocalPosition> positions) {
    Map<Integer, LocalPosition> byNumber = new LinkedHashMap<>();
    for (LocalPosition p : positions) {
      byNumber.put(p.number(), p);
    }
    return new Program(name, Map.of(), "", lines, byNumber);
  }

  /**
   * The /ATTR key under which the program's sub-type ({@code Macro}, {@code Cond}, {@code Job},
   * {@code Process}) is kept: it is written on the /PROG line, not in /ATTR.
   */
  public static final String SUBTYPE_KEY = "/PROG SUBTYPE";

  /**
   * Whether {@code name} is a valid program name: letters, digits and '_', not starting with a
   * digit, at most 36 characters. Controllers write names that start with '_' (background logic
   * and system programs such as {@code _BGT_BTN_ABORT}).
   */
  public static boolean isValidName(String name) {
    // A leading '-' is a controller's way to list a program it keeps apart (seen in real listings).
    int first = name.startsWith("-") ? 1 : 0;
    if (name.length() <= first || name.length() > MAX_NAME_LENGTH
        || !(isAsciiLetter(name.charAt(first)) || name.charAt(first) == '_')) {
      return false;
    }
    for (int i = first + 1; i < name.length(); i++) {
      char c = name.charAt(i);
      if (!isAsciiLetter(c) && !(c >= '0' && c <= '9') && c != '_') {
        return false;
      }
    }
    return true;
  }

  private static boolean isAsciiLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
  }

  /** This program with other lines and positions, keeping the source text it was read from. */
  public Program withBody(List<Instruction> newLines, Map<Integer, LocalPosition> newPositions) {
    return new Program(name, attributes, comment, newLines, newPositions, source);
  }

  /** This program without its source text (as if never read from a file). */
  public Program withoutSource() {
    return source.isEmpty() ? this : new Program(name, attributes, comment, lines, positions);
  }

  /** Equality of the program's value: name, attributes, comment, lines and positions (not the source text). */
  @Override
  public boolean equals(Object o) {
    return o instanceof Program p && name.equals(p.name) && attributes.equals(p.attributes)
        && comment.equals(p.comment) && lines.equals(p.lines) && positions.equals(p.positions);
  }

  @Override
  public int hashCode() {
    return Objects.hash(name, attributes, comment, lines, positions);
  }

  @Override
  public String toString() {
    return "Program[name=" + name + ", attributes=" + attributes + ", comment=" + comment + ", lines=" + lines
        + ", positions=" + positions + "]";
  }

  /** Number of /MN lines. */
  public int lineCount() {
    return lines.size();
  }

  /** Line {@code number} (1-based). */
  public Instruction line(int number) {
    return lines.get(number - 1);
  }

  /** The local position P[number], if the /POS block has it. */
  public Optional<LocalPosition> position(int number) {
    return Optional.ofNullable(positions.get(number));
  }
}
