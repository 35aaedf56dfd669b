package org.robotrun.grade;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * One graded check of a task (docs/grading.md): what is measured, and on which runs. Every check
 * carries its {@link Meta}: name, points, the message a student sees when it fails, whether it
 * is hidden from students, and which runs it looks at.
 */
public sealed interface Check {
  Meta meta();

  /** Which simulated runs a run-based check looks at; it passes only if it passes in each. */
  enum Runs {
    /** The task's scenario as it is. */
    NOMINAL,
    /** Each seeded variation. */
    VARIATIONS,
    /** The nominal run and every variation. */
    ALL
  }

  /**
   * @param name unique within the task; the Gradescope test name and the CSV column
   * @param points what the check is worth (0 = feedback only)
   * @param message for the student when it fails ("" = none beyond what was measured)
   * @param hidden not shown to students (Gradescope visibility "hidden"; not run by Check my work)
   * @param robot the robot a robot check looks at, by name; empty: the first robot (or the whole
   *     cell, for the checks that look at the cell: parts, collisions)
   */
  record Meta(String name, double points, String message, boolean hidden, Runs runs, Optional<String> robot) {
    public Meta(String name, double points, String message, boolean hidden, Runs runs) {
      this(name, points, message, hidden, runs, Optional.empty());
    }
  }

  /** The submission is a valid hand-in zip: manifest, every file listed with its SHA-256. */
  record HandIn(Meta meta) implements Check {}

  /** Every program reads without errors (as {@code robotrun check}), CALL targets included. */
  record ProgramsCheck(Meta meta) implements Check {}

  /** The main program reaches its end; or, with {@code alarm}, stops with that alarm code. */
  record RunsToEnd(Meta meta, Optional<String> alarm) implements Check {}

  /**
   * {@code part} ends resting on {@code fixture}, its origin at {@code p_FP} (mm, in the
   * fixture's frame) within {@code toleranceMm}, and, if {@code rDeg} is given, turned by that
   * angle about the fixture's z axis within {@code toleranceDeg}. Not held by a robot.
   */
  record PartAt(Meta meta, String part, String fixture, Vec3 p_FP, double toleranceMm, Optional<Double> rDeg,
      double toleranceDeg) implements Check {}

  /** No part is left in a gripper at the end. */
  record NothingHeld(Meta meta) implements Check {}

  /** No part was let go in the air: every part that moved rests on a fixture. */
  record NoneDropped(Meta meta) implements Check {}

  /** At most {@code maxWarnings} collisions (0: none); a collision alarm always fails. */
  record NoCollision(Meta meta, int maxWarnings) implements Check {}

  /** No joint-limit, reach or singularity stop (MOTN-017, MOTN-018, MOTN-023). */
  record NoMotionStop(Meta meta) implements Check {}

  /** The program ends within {@code maxSec} simulated seconds. */
  record CycleTime(Meta meta, double maxSec) implements Check {}

  /** What the program text uses: features required and forbidden, at most so many motion lines. */
  record ProgramUse(Meta meta, Set<Feature> requires, Set<Feature> forbids, OptionalInt maxMotionLines)
      implements Check {}

  /** Registers, flags and I/O at the end, by name ("R[1]", "DO[3]", "F[2]", "GO[1]"). */
  record EndState(Meta meta, Map<String, Double> expected, double tolerance) implements Check {}

  /** A taught frame (tool or user, number 1..10) within a tolerance of the true one. */
  record Frame(Meta meta, boolean tool, int number, Transform truth, double toleranceMm, double toleranceDeg)
      implements Check {}

  /**
   * A position register as the student recorded it (the submission's saved state, or what the
   * window holds), not as a run leaves it: its X, Y, Z within {@code toleranceMm} of
   * {@code position} (mm, in the frame the task says it is recorded in).
   */
  record PositionRegister(Meta meta, int number, Vec3 position, double toleranceMm) implements Check {}

  /**
   * The first robot's active TCP passes within {@code toleranceMm} of each of {@code points_W}
   * (mm, WORLD) at some time during the run, in any order.
   */
  record TcpVisits(Meta meta, List<Vec3> points_W, double toleranceMm) implements Check {
    public TcpVisits {
      points_W = List.copyOf(points_W);
    }
  }

  /** Program features a {@link ProgramUse} check can require or forbid. */
  enum Feature {
    /** A motion with {@code Offset,PR[i]}. */
    OFFSET_PR("offsetPR", "a motion with Offset,PR[...]"),
    /** A motion with {@code Tool_Offset,PR[i]}. */
    TOOL_OFFSET_PR("toolOffsetPR", "a motion with Tool_Offset,PR[...]"),
    /** A motion to a position register. */
    PR_TARGET("prTarget", "a motion to a position register PR[...]"),
    FOR("for", "a FOR loop"),
    CALL("call", "a CALL"),
    /** A {@code JMP LBL[n]} to a label on an earlier line. */
    JMP_BACKWARD("jmpBackward", "a JMP to a label above it"),
    WAIT("wait", "a WAIT"),
    IF("if", "an IF"),
    SELECT("select", "a SELECT"),
    /** A joint motion (J). */
    JOINT_MOTION("joint", "a joint motion (J)"),
    /** A linear motion (L). */
    LINEAR_MOTION("linear", "a linear motion (L)"),
    /** A circular motion (C or A). */
    CIRCULAR_MOTION("circular", "a circular motion (C or A)"),
    /** A motion ending CNT (a blended corner). */
    CNT("cnt", "a motion ending CNT"),
    /** A motion ending FINE. */
    FINE("fine", "a motion ending FINE"),
    /** RUN of another program (a task beside the main one). */
    RUN("run", "a RUN of another program"),
    /** A motion with {@code VOFFSET,VR[i]} (a vision offset). */
    VOFFSET("voffset", "a motion with VOFFSET,VR[...]");

    final String key;
    final String words;

    Feature(String key, String words) {
      this.key = key;
      this.words = words;
    }

    /** The name used in task files. */
    public String key() {
      return key;
    }

    /** Words for a message. */
    public String words() {
      return words;
    }

    static Optional<Feature> byKey(String key) {
      for (Feature f : values()) {
        if (f.key.equals(key)) {
          return Optional.of(f);
        }
      }
      return Optional.empty();
    }

    static List<String> keys() {
      return java.util.Arrays.stream(values()).map(Feature::key).toList();
    }
  }
}
