package org.robotrun.program;

import java.util.List;
import java.util.Objects;

/**
 * Parts of a motion statement {@code type target speed termination [options]}. The statement
 * itself is {@link Instruction.Move}.
 */
public final class Motion {
  private Motion() {}

  /** J joint, L linear, C circular (via + end), A circular arc through consecutive A points. */
  public enum Type {
    J, L, C, A
  }

  /** Where a motion goes: a local {@code P[n]} or a position register {@code PR[n]} / {@code PR[R[i]]}. */
  public sealed interface Target {}

  /** {@code P[n:comment]}: a position of the program's /POS block. */
  public record Local(int number, String comment) implements Target {
    public Local {
      Objects.requireNonNull(comment, "comment");
    }
  }

  /** {@code PR[n:comment]} or {@code PR[R[i]]}. */
  public record Register(Item register) implements Target {
    public Register {
      Objects.requireNonNull(register, "register");
    }
  }

  /** Speed units; which fit which motion type is {@link #fits(Type)}. */
  public enum SpeedUnit {
    /** {@code %} of maximum joint speed (J only). */
    PERCENT,
    /** {@code sec}: motion time. */
    SEC,
    /** {@code msec}: motion time. */
    MSEC,
    MM_PER_SEC, CM_PER_MIN, INCH_PER_MIN,
    /** {@code deg/sec}: orientation speed (L/C/A). */
    DEG_PER_SEC;

    /** Whether this unit is allowed for the motion type (TP-LANGUAGE.md, speed row). */
    public boolean fits(Type type) {
      return switch (this) {
        case SEC, MSEC -> true;
        case PERCENT -> type == Type.J;
        case MM_PER_SEC, CM_PER_MIN, INCH_PER_MIN, DEG_PER_SEC -> type != Type.J;
      };
    }
  }

  /** The number in a speed: a constant ({@code 400}) or a data register ({@code R[3]}). */
  public sealed interface SpeedValue {}

  /** {@code 400mm/sec}, {@code 30%}, {@code 0.5sec}. */
  public record SpeedConst(double value) implements SpeedValue {}

  /** {@code R[i]%}, {@code R[i]mm/sec}. */
  public record SpeedRegister(Item register) implements SpeedValue {
    public SpeedRegister {
      Objects.requireNonNull(register, "register");
    }
  }

  /** A speed value with its unit. */
  public record Speed(SpeedValue value, SpeedUnit unit) {
    public Speed {
      Objects.requireNonNull(value, "value");
      Objects.requireNonNull(unit, "unit");
    }
  }

  /** How a motion ends: {@code FINE}, {@code CNTn} or {@code CNT R[i]}. */
  public sealed interface Termination {}

  /** {@code FINE}: stop exactly at the point. */
  public record Fine() implements Termination {}

  /** {@code CNTn}, n in 0..100: blend into the next motion (larger blends earlier). */
  public record Cnt(int value) implements Termination {}

  /** {@code CNT R[i]}. */
  public record CntRegister(Item register) implements Termination {
    public CntRegister {
      Objects.requireNonNull(register, "register");
    }
  }

  /** Motion options, in the order written. */
  public sealed interface Option {}

  /** {@code Offset}: shifts by the PR named in the last OFFSET CONDITION (an alarm without one). */
  public record Offset() implements Option {}

  /** {@code Offset,PR[i]}: shifts the target by PR[i] in the active user frame. */
  public record OffsetPr(Item register) implements Option {
    public OffsetPr {
      Objects.requireNonNull(register, "register");
    }
  }

  /** {@code Tool_Offset,PR[i]}: shifts the target by PR[i] in the tool frame. */
  public record ToolOffsetPr(Item register) implements Option {
    public ToolOffsetPr {
      Objects.requireNonNull(register, "register");
    }
  }

  /**
   * {@code VOFFSET,VR[i]}: shifts the target by the offset the vision register holds, in its user
   * frame (iRVision, docs/vision.md).
   */
  public record VisionOffset(Item vr) implements Option {
    public VisionOffset {
      Objects.requireNonNull(vr, "vr");
    }
  }

  /** {@code ACCn}: acceleration override in percent. */
  public record Acc(int percent) implements Option {}

  /**
   * {@code Skip,LBL[i]}: the motion stops when the SKIP CONDITION turns true (the program goes on
   * with the next line); it jumps to the label when the motion ends without the condition.
   */
  public record Skip(LabelRef label) implements Option {
    public Skip {
      Objects.requireNonNull(label, "label");
    }
  }

  /** {@code Wjnt}: keep the wrist joints' attitude during a linear/circular motion. */
  public record Wjnt() implements Option {}

  /** {@code INC}: the target is an increment from the current position. */
  public record Inc() implements Option {}

  /** When a {@link TimedAction} fires. */
  public enum When {
    /** {@code TB t sec,...}: t seconds before the motion reaches its point. */
    TIME_BEFORE,
    /** {@code TA t sec,...}: t seconds after it. */
    TIME_AFTER,
    /** {@code DB d mm,...}: when the TCP comes within d mm (straight line) of the point. */
    DISTANCE_BEFORE;

    /** The option as a controller names it in alarms ({@code "TIME BEFORE"}). */
    public String label() {
      return name().replace('_', ' ');
    }
  }

  /**
   * {@code TB t sec,action}, {@code TA t sec,action} or {@code DB d mm,action} with an action
   * RobotRun runs: an output ({@code DO[1]=ON}, {@code RO[2]=PULSE,0.5sec}, {@code GO[1]=R[3]} ...)
   * or {@code CALL PROG} (no arguments), whose program runs beside the motion.
   *
   * @param amount seconds (TB, TA) or millimetres (DB)
   * @param text the option as written ({@code "TB   .20sec,DO[1]=ON"}), so it is written back unchanged
   */
  public record TimedAction(When when, double amount, Instruction action, String text) implements Option {
    public TimedAction {
      Objects.requireNonNull(when, "when");
      Objects.requireNonNull(action, "action");
      Objects.requireNonNull(text, "text");
      if (!(action instanceof Instruction.SetIo || action instanceof Instruction.Pulse
          || action instanceof Instruction.Call c && c.args().isEmpty())) {
        throw new IllegalArgumentException("a TB/TA/DB action RobotRun runs is an output or a CALL without arguments: "
            + action);
      }
      if (!(amount >= 0) || Double.isInfinite(amount)) {
        throw new IllegalArgumentException("expected 0 or more, got " + amount);
      }
    }
  }

  /**
   * A motion option the controller has and RobotRun does not run yet ({@code TB .50sec,CALL X},
   * {@code VOFFSET} with a VOFFSET CONDITION, {@code PTH}, {@code RTCP}): the rest of the line from the option on,
   * kept as written. The motion itself runs without it; {@code check} says so.
   *
   * @param text the option text as written, e.g. {@code "TB   .50sec,CALL OPEN"}
   * @param what the kind, as the message names it ({@code "TIME BEFORE (TB)"})
   */
  public record RawOption(String text, String what) implements Option {
    public RawOption {
      Objects.requireNonNull(text, "text");
      Objects.requireNonNull(what, "what");
    }
  }

  /** Options list helper: an unmodifiable copy. */
  static List<Option> copyOptions(List<Option> options) {
    return List.copyOf(Objects.requireNonNull(options, "options"));
  }
}
