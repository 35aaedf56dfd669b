package org.robotrun.pendant;

import java.util.List;
import java.util.Objects;
import org.robotrun.pendant.ExprText.BadText;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;
import org.robotrun.program.TpText;
import org.robotrun.program.DefaultMotions;
import org.robotrun.program.Instruction;
import org.robotrun.program.Motion;

/**
 * The motion POINT records ({@code J P[] 100% FINE}): type, speed and termination. The operator
 * picks one of the standard four or edits its own.
 */
record DefaultMotion(Motion.Type type, Motion.Speed speed, Motion.Termination termination) {
  DefaultMotion {
    Objects.requireNonNull(type, "type");
    Objects.requireNonNull(speed, "speed");
    Objects.requireNonNull(termination, "termination");
  }

  /** FANUC's four standard defaults (the one table, {@link DefaultMotions#STANDARD}). */
  static final List<DefaultMotion> STANDARD = DefaultMotions.STANDARD.stream()
      .map(r -> new DefaultMotion(r.type(), r.speed(), r.termination())).toList();

  /** The motion line to P[n] (C motion records the via point; its end point is the next number). */
  Instruction.Move line(int positionNumber) {
    Motion.Local target = new Motion.Local(positionNumber, "");
    if (type == Motion.Type.C) {
      return Instruction.Move.circular(target, new Motion.Local(positionNumber + 1, ""), speed, termination, List.of());
    }
    return Instruction.Move.of(type, target, speed, termination, List.of());
  }

  /** {@code L P[] 200mm/sec CNT50}. */
  String display() {
    return type + " P[] " + TpText.speed(speed) + " " + TpText.termination(termination);
  }

  /**
   * Parses {@code L 200mm/sec CNT50} / {@code J 50% FINE} / {@code L R[2]mm/sec CNT R[3]} (the
   * "P[]" is optional) with the one parser, as the motion line {@code L P[1] 200mm/sec CNT50}.
   */
  static DefaultMotion parse(String text) throws BadText {
    return parse(text, TpLine.DEFAULT_MAX_MM_PER_SEC);
  }

  /** As above for a robot whose maximum TCP speed is {@code maxMmPerSec} (mm/s). */
  static DefaultMotion parse(String text, double maxMmPerSec) throws BadText {
    String t = text.trim().replace("P[]", " ").trim();
    int space = t.indexOf(' ');
    if (space < 0) {
      throw new BadText("expected 'type speed termination', e.g. L 200mm/sec CNT50");
    }
    Motion.Type type;
    try {
      type = Motion.Type.valueOf(t.substring(0, space).toUpperCase(java.util.Locale.ROOT));
    } catch (IllegalArgumentException e) {
      throw new BadText("motion type must be J, L, C or A, got '" + t.substring(0, space) + "'");
    }
    String target = type == Motion.Type.C ? " P[1]\n    : P[2] " : " P[1] ";
    Instruction in;
    try {
      in = TpStatementParser.statementText(type + target + t.substring(space + 1).trim()).instruction();
    } catch (TpSyntaxError e) {
      throw new BadText(e.getMessage() + " (expected 'type speed termination', e.g. L 200mm/sec CNT50)");
    }
    if (!(in instanceof Instruction.Move m) || !m.options().isEmpty()) {
      throw new BadText("expected 'type speed termination', e.g. L 200mm/sec CNT50");
    }
    return new DefaultMotion(type, TpLine.checkedSpeed(m.speed(), maxMmPerSec), m.termination());
  }
}
