package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.control.RobotControl;
import org.robotrun.motion.JogState;
import org.robotrun.program.Program;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;

/**
 * Every library model in the default cell: a short program (a joint move to a taught joint
 * position, then a linear move to a Cartesian position taught with its CONFIG) and a jog in
 * each frame, the way a student would use a new robot.
 */
class RobotLibraryCellTest {
  /** Pendant degrees of the start pose: off every singularity, inside every model's limits. */
  static final double[] START = {10, 20, -10, 15, -60, 20};
  static final double[] END = {25, 28, -4, 5, -50, 35};

  static Stream<String> models() {
    return RobotDefinitions.LIBRARY.stream();
  }

  private static double[] kinematic(RobotModel m, double[] pendantDeg) {
    double[] r = new double[6];
    for (int i = 0; i < 6; i++) {
      r[i] = Math.toRadians(pendantDeg[i]);
    }
    return JointConvention.pendantToKinematic(m, r);
  }

  private static Program program(RobotModel m) {
    double[] q2 = kinematic(m, END);
    // UF1 = WORLD, UT1 = the default cell's 100 mm pointer.
    Transform X_WT = ForwardKinematics.flangePoseInWorld(m, q2).compose(Transform.translation(0, 0, DefaultCell.POINTER_MM));
    Xyzwpr p = Xyzwpr.fromTransform(X_WT);
    Config config = IkSolver.forModel(m).configOf(q2);
    String text = String.format(Locale.ROOT, """
        /PROG  SHORT
        /ATTR
        /MN
           1:J P[1:START] 50%% FINE ;
           2:L P[2:END] 250mm/sec FINE ;
        /POS
        P[1:"START"]{
           GP1:
        	UF : 1, UT : 1,
        	J1= %.3f deg,	J2= %.3f deg,	J3= %.3f deg,
        	J4= %.3f deg,	J5= %.3f deg,	J6= %.3f deg
        };
        P[2:"END"]{
           GP1:
        	UF : 1, UT : 1,		CONFIG : '%s',
        	X = %.4f  mm,	Y = %.4f  mm,	Z = %.4f  mm,
        	W = %.4f deg,	P = %.4f deg,	R = %.4f deg
        };
        /END
        """, START[0], START[1], START[2], START[3], START[4], START[5], config,
        p.x(), p.y(), p.z(), Math.toDegrees(p.w()), Math.toDegrees(p.p()), Math.toDegrees(p.r()));
    return LsReader.parse("SHORT.LS", text).program();
  }

  @ParameterizedTest
  @MethodSource("models")
  void aShortProgramEndsOnItsCartesianTargetInItsConfig(String id) {
    RobotModel m = RobotDefinitions.load(id);
    Simulation sim = DefaultCell.simulation(m);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program(m));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "SHORT", 60, s -> {});
    assertThat(r.status()).as(id + " " + r.alarm()).isEqualTo(HeadlessRun.Status.FINISHED);
    double[] q = c.jointsRad();
    double[] want = kinematic(m, END);
    for (int i = 0; i < 6; i++) {
      // The taught position is written to 1e-4 mm and 1e-4 deg.
      assertThat(q[i]).as("%s J%d", id, i + 1).isCloseTo(want[i], offset(1e-4));
    }
  }

  @ParameterizedTest
  @MethodSource("models")
  void jogsInEveryFrameMoveTheArmWithoutChangingItsConfig(String id) {
    RobotModel m = RobotDefinitions.load(id);
    IkSolver ik = IkSolver.forModel(m);
    for (RobotControl.CoordSystem frame : RobotControl.CoordSystem.values()) {
      // Each frame from the program's end pose (off every singularity).
      Simulation sim = DefaultCell.simulation(m);
      Controller c = sim.controllers().get(0);
      c.saveProgram(program(m));
      assertThat(HeadlessRun.run(sim, c, "SHORT", 60, s -> {}).status()).isEqualTo(HeadlessRun.Status.FINISHED);
      c.setMode(RobotControl.Mode.T1);
      c.setDeadman(true);
      c.setOverridePct(50);
      c.setCoordSystem(frame);
      for (int axis = 1; axis <= 6; axis++) {
        double[] q0 = c.jointsRad();
        Config before = ik.configOf(q0);
        Xyzwpr p0 = c.tcpInWorld();
        assertThat(c.jogKeyDown(axis, +1, JogState.Press.HELD)).as("%s %s axis %d", id, frame, axis)
            .isInstanceOf(RobotControl.Result.Ok.class);
        for (int i = 0; i < 150; i++) {
          sim.step();
        }
        c.jogKeyUp(axis, +1);
        for (int i = 0; i < 30; i++) {
          sim.step();
        }
        double[] q1 = c.jointsRad();
        Xyzwpr p1 = c.tcpInWorld();
        String what = id + " " + frame + " axis " + axis;
        assertThat(c.alarmHistory()).as(what).isEmpty();
        if (frame == RobotControl.CoordSystem.JOINT) {
          assertThat(q1[axis - 1] - q0[axis - 1]).as(what).isGreaterThan(0.01);
        } else {
          double moved = axis <= 3
              ? Math.hypot(Math.hypot(p1.x() - p0.x(), p1.y() - p0.y()), p1.z() - p0.z())
              : p1.toTransform().rotationAngleTo(p0.toTransform());
          assertThat(moved).as(what).isGreaterThan(axis <= 3 ? 5 : 0.05);
          Config after = ik.configOf(q1);
          assertThat(after.sameBranch(before)).as(what + ": " + before + " -> " + after).isTrue();
        }
        // Back where it started, so each axis starts off the singularities too.
        assertThat(c.jogKeyDown(axis, -1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
        for (int i = 0; i < 150; i++) {
          sim.step();
        }
        c.jogKeyUp(axis, -1);
        for (int i = 0; i < 30; i++) {
          sim.step();
        }
      }
    }
  }
}
