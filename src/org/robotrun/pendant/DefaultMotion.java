package org.robotrun.pendant;

import java.util.List;
import java.util.Objects;
import org.robotrun.pendant.ExprText.BadText;
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

  /** FANUC's four standard defaults. */
  static final List<DefaultMotion> STANDARD = List.of(
      new DefaultMotion(Motion.Type.J, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT), new Motion.Fine()),
      new DefaultMotion(Motion.Type.J, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT), new Motion.Cnt(100)),
      new DefaultMotion(Motion.Type.L, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC), new Motion.Fine()),
      new DefaultMotion(Motion.Type.L, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC), new Motion.Cnt(100)));

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
    String speedText = switch (speed.value()) {
      case Motion.SpeedConst c -> ExprText.plain(c.value());
      case Motion.SpeedRegister r -> ExprText.item("R", r.register());
    };
    String term = switch (termination) {
      case Motion.Fine f -> "FINE";
      case Motion.Cnt c -> "CNT" + c.value();
      case Motion.CntRegister r -> "CNT " + ExprText.item("R", r.register());
    };
    return type + " P[] " + speedText + TpLine.unit(speed.unit()) + " " + term;
  }

  /** Parses {@code L 200mm/sec CNT50} / {@code J 50% FINE} (the "P[]" is optional). */
  static DefaultMotion parse(String text) throws BadText {
    return parse(text, TpLine.DEFAULT_MAX_MM_PER_SEC);
  }

  /** As above for a robot whose maximum TCP speed is {@code maxMmPerSec} (mm/s). */
  static DefaultMotion parse(String text, double maxMmPerSec) throws BadText {
    String[] parts = text.trim().replace("P[]", " ").trim().split("\\s+");
    if (parts.length != 3) {
      throw new BadText("expected 'type speed termination', e.g. L 200mm/sec CNT50");
    }
    Motion.Type type;
    try {
      type = Motion.Type.valueOf(parts[0].toUpperCase(java.util.Locale.ROOT));
    } catch (IllegalArgumentException e) {
      throw new BadText("motion type must be J, L, C or A, got '" + parts[0] + "'");
    }
    String s = parts[1];
    int split = 0;
    while (split < s.length() && (Character.isDigit(s.charAt(split)) || s.charAt(split) == '.')) {
      split++;
    }
    String unitText = s.substring(split);
    Motion.SpeedUnit unit = null;
    for (Motion.SpeedUnit u : Motion.SpeedUnit.values()) {
      if (TpLine.unit(u).equalsIgnoreCase(unitText)) {
        unit = u;
      }
    }
    if (unit == null) {
      throw new BadText("unknown speed unit '" + unitText + "' (%, mm/sec, cm/min, inch/min, deg/sec, sec, msec)");
    }
    if (!unit.fits(type)) {
      throw new BadText("speed unit " + unitText + " does not fit " + type + " motion");
    }
    double v = NumberEntry.positive("Speed", s.substring(0, split));
    Motion.Termination term = TpLine.parseTermination(parts[2]);
    return new DefaultMotion(type, TpLine.checkedSpeed(new Motion.Speed(new Motion.SpeedConst(v), unit), maxMmPerSec), term);
  }
}
