package org.robotrun.program;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The iRVision statements RobotRun runs, read from the text the grammar keeps for them
 * ({@link Instruction.Unsupported} and {@link Motion.RawOption} hold them as written, so a file
 * is written back unchanged). Forms (TP-LANGUAGE.md; docs/vision.md):
 *
 * <pre>
 *   VISION RUN_FIND 'NAME'
 *   VISION GET_OFFSET 'NAME' VR[i] JMP,LBL[j]
 *   VISION GET_NFOUND 'NAME' R[i]
 *   PR[i]=VR[j].OFFSET          PR[i]=VR[j].FOUND_POS[1]
 *   R[i]=VR[j].MODELID          R[i]=VR[j].ENC          R[i]=VR[j].MES[k]
 *   ... VOFFSET,VR[i]           (motion option)
 * </pre>
 *
 * where i and j are a number or R[n] (indirect); items may carry a comment ({@code PR[20:FOUND]}).
 */
public sealed interface VisionStatement {

  record RunFind(String process) implements VisionStatement {}

  record GetOffset(String process, Index register, LabelRef label) implements VisionStatement {}

  record GetNFound(String process, Index register) implements VisionStatement {}

  /** {@code PR[i]=VR[j].OFFSET} ({@code foundPos} false) or {@code .FOUND_POS[1]} (true). */
  record PositionFromVr(Index target, Index vr, boolean foundPos) implements VisionStatement {}

  /** {@code R[i]=VR[j].field}; {@code element} is the MES index (1..10), 0 otherwise. */
  record NumberFromVr(Index target, Index vr, Field field, int element) implements VisionStatement {}

  /** The numeric fields of a vision register. */
  enum Field {
    MODELID, ENC, MES
  }

  String IDX = "(\\d+|R\\[\\s*\\d+\\s*(?::[^\\]]*)?\\])";
  String COMMENT = "\\s*(?::[^\\]]*)?\\]";
  String NAME = "'([^']*)'";

  Pattern RUN_FIND = Pattern.compile("(?i)VISION\\s+RUN_FIND\\s+" + NAME + "\\s*");
  Pattern GET_OFFSET = Pattern.compile("(?i)VISION\\s+GET_OFFSET\\s+" + NAME + "\\s+VR\\[\\s*" + IDX + COMMENT
      + "\\s+JMP\\s*,?\\s*LBL\\[\\s*" + IDX + "\\s*(?::([^\\]]*))?\\]\\s*");
  Pattern GET_NFOUND = Pattern.compile("(?i)VISION\\s+GET_NFOUND\\s+" + NAME + "\\s+R\\[\\s*" + IDX + COMMENT + "\\s*");
  Pattern PR_FROM_VR = Pattern.compile("(?i)PR\\[\\s*" + IDX + COMMENT + "\\s*=\\s*VR\\[\\s*" + IDX + COMMENT
      + "\\.(OFFSET|FOUND_POS\\[\\s*1\\s*\\])\\s*");
  Pattern R_FROM_VR = Pattern.compile("(?i)R\\[\\s*" + IDX + COMMENT + "\\s*=\\s*VR\\[\\s*" + IDX + COMMENT
      + "\\.(MODELID|ENC|MES\\[\\s*(\\d+)\\s*\\])\\s*");
  Pattern VOFFSET = Pattern.compile("(?i)VOFFSET\\s*,\\s*VR\\[\\s*" + IDX + COMMENT + "\\s*");

  /** The statement {@code text} (as an Unsupported line keeps it), if it is one RobotRun runs. */
  static Optional<VisionStatement> parse(String text) {
    try {
      return parseOrThrow(text.strip());
    } catch (NumberFormatException e) {
      return Optional.empty(); // an index too large for an int: not a form RobotRun runs
    }
  }

  private static Optional<VisionStatement> parseOrThrow(String t) {
    Matcher m = RUN_FIND.matcher(t);
    if (m.matches()) {
      return Optional.of(new RunFind(m.group(1)));
    }
    m = GET_OFFSET.matcher(t);
    if (m.matches()) {
      return Optional.of(new GetOffset(m.group(1), index(m.group(2)), new LabelRef(index(m.group(3)),
          m.group(4) == null ? "" : m.group(4))));
    }
    m = GET_NFOUND.matcher(t);
    if (m.matches()) {
      return Optional.of(new GetNFound(m.group(1), index(m.group(2))));
    }
    m = PR_FROM_VR.matcher(t);
    if (m.matches()) {
      return Optional.of(new PositionFromVr(index(m.group(1)), index(m.group(2)),
          !m.group(3).equalsIgnoreCase("OFFSET")));
    }
    m = R_FROM_VR.matcher(t);
    if (m.matches()) {
      String f = m.group(3).toUpperCase(java.util.Locale.ROOT);
      Field field = f.startsWith("MES") ? Field.MES : Field.valueOf(f);
      int element = field == Field.MES ? Integer.parseInt(m.group(4)) : 0;
      if (field == Field.MES && (element < 1 || element > 10)) {
        return Optional.empty();
      }
      return Optional.of(new NumberFromVr(index(m.group(1)), index(m.group(2)), field, element));
    }
    return Optional.empty();
  }

  /** True when RobotRun runs the statement {@code text} (so {@code check} need not report it). */
  static boolean runs(String text) {
    return parse(text).isPresent();
  }

  /** The VR index of a {@code VOFFSET,VR[i]} motion option's text, if it is one. */
  static Optional<Index> voffset(String optionText) {
    Matcher m = VOFFSET.matcher(optionText.strip());
    try {
      return m.matches() ? Optional.of(index(m.group(1))) : Optional.empty();
    } catch (NumberFormatException e) {
      return Optional.empty();
    }
  }

  private static Index index(String s) {
    String t = s.strip();
    if (Character.isDigit(t.charAt(0))) {
      return new Index.Direct(Integer.parseInt(t));
    }
    String inner = t.substring(t.indexOf('[') + 1, t.indexOf(']')).strip();
    int colon = inner.indexOf(':');
    String num = (colon < 0 ? inner : inner.substring(0, colon)).strip();
    return new Index.Indirect(Integer.parseInt(num), colon < 0 ? "" : inner.substring(colon + 1));
  }
}
