package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.control.RobotControl;
import org.robotrun.io.LsReader;
import org.robotrun.io.TestArms;
import org.robotrun.io.UrdfImporter;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.motion.JogState;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.RobotModel;

/**
 * An imported UR-layout arm (the importer tests' UR5-like package) in the controller: a program
 * with a joint move and a linear move to a Cartesian position taught with its CONFIG ends on the
 * taught joints, and Cartesian jogs keep the CONFIG (the UR-type closed form, not the numeric
 * solver, decides the branch).
 */
class ImportedUrArmCellTest {
  @TempDir
  Path tmp;

  static final double[] START = {10, -70, 80, -100, -80, 20};
  static final double[] END = {25, -80, 95, -105, -70, 35};

  private static double[] rad(double[] deg) {
    double[] r = new double[6];
    for (int i = 0; i < 6; i++) {
      r[i] = Math.toRadians(deg[i]);
    }
    return r;
  }

  private static String program(RobotModel m) {
    double[] q2 = rad(END);
    Transform X_WT = ForwardKinematics.flangePoseInWorld(m, q2).compose(Transform.translation(0, 0, DefaultCell.POINTER_MM));
    Xyzwpr p = Xyzwpr.fromTransform(X_WT);
    Config config = IkSolver.forModel(m).configOf(q2);
    return String.format(Locale.ROOT, """
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
  }

  @Test
  void aProgramEndsOnItsTaughtJointsAndJogsKeepTheConfig() throws Exception {
    RobotModel m = UrdfImporter.importRobot(TestArms.offsetPackage(tmp), Map.of()).model();
    assertThat(IkSolver.forModel(m).kind()).isEqualTo("ur-type");
    // The default cell's frames, but starting at START: a UR at HOME (q = 0 but J5) has its wrist at the floor.
    Controller c = new Controller("robot1", m, new org.robotrun.program.Position.Joint(START[0], START[1], START[2], START[3],
        START[4], START[5]));
    c.frames().setTransform(org.robotrun.program.Instruction.FrameKind.TOOL, 1, Transform.translation(0, 0, DefaultCell.POINTER_MM));
    c.frames().select(org.robotrun.program.Instruction.FrameKind.TOOL, 1);
    c.frames().select(org.robotrun.program.Instruction.FrameKind.USER, 1);
    Simulation sim = Simulation.of(c);
    c.saveProgram(LsReader.parse("SHORT.LS", program(m)).program());
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "SHORT", 60, s -> {});
    assertThat(r.status()).as(String.valueOf(r.alarm())).isEqualTo(HeadlessRun.Status.FINISHED);
    double[] q = c.jointsRad();
    double[] want = rad(END);
    for (int i = 0; i < 6; i++) {
      assertThat(q[i]).as("J%d", i + 1).isCloseTo(want[i], offset(1e-4));
    }
    IkSolver ik = IkSolver.forModel(m);
    c.setMode(RobotControl.Mode.T1);
    c.setDeadman(true);
    c.setOverridePct(50);
    c.setCoordSystem(RobotControl.CoordSystem.WORLD);
    for (int axis = 1; axis <= 6; axis++) {
      Config before = ik.configOf(c.jointsRad());
      Xyzwpr p0 = c.tcpInWorld();
      assertThat(c.jogKeyDown(axis, +1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
      for (int i = 0; i < 100; i++) {
        sim.step();
      }
      c.jogKeyUp(axis, +1);
      for (int i = 0; i < 30; i++) {
        sim.step();
      }
      Xyzwpr p1 = c.tcpInWorld();
      assertThat(c.alarmHistory()).as("axis %d", axis).isEmpty();
      double moved = axis <= 3 ? Math.hypot(Math.hypot(p1.x() - p0.x(), p1.y() - p0.y()), p1.z() - p0.z())
          : p1.toTransform().rotationAngleTo(p0.toTransform());
      assertThat(moved).as("axis %d", axis).isGreaterThan(axis <= 3 ? 5 : 0.05);
      assertThat(ik.configOf(c.jointsRad()).sameBranch(before)).as("axis %d", axis).isTrue();
    }
  }
}
