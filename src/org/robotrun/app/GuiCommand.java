package org.robotrun.app;

import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.math.Angles;
import org.robotrun.math.Xyzwpr;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.ui.RobotStatusPanel;
import org.robotrun.sim.SceneSnapshots;
import org.robotrun.ui.SimulatorWindow;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun gui} (also what {@code robotrun} alone does): the simulator window. */
@Command(
    name = "gui",
    mixinStandardHelpOptions = true,
    description = {
      "Open the simulator window (what 'robotrun' with no subcommand does).",
      "Mouse: left drag orbits, right or middle drag pans, wheel zooms. Home or R resets the view; Escape closes the window."
    })
public final class GuiCommand implements Callable<Integer> {
  @Option(names = "--width", defaultValue = "1280", description = "Window width (default: ${DEFAULT-VALUE}).")
  int width = 1280;

  @Option(names = "--height", defaultValue = "800", description = "Window height (default: ${DEFAULT-VALUE}).")
  int height = 800;

  @Option(names = "--joints", paramLabel = "J1,...,J6",
      description = "Starting joint angles in degrees as the pendant shows them. Default: all 0.")
  String joints;

  @Override
  public Integer call() {
    RenderCommand.checkSize("--width", width);
    RenderCommand.checkSize("--height", height);
    RobotModel robot = RobotDefinitions.defaultRobot();
    double[] q = joints == null ? new double[RobotModel.DOF] : JointsOption.parseToKinematic(joints, robot);
    try (SimulatorWindow w = new SimulatorWindow("RobotRun — " + robot.displayName(), width, height)) {
      double[] pendantDeg = Angles.toDegrees(JointConvention.kinematicToPendant(robot, q));
      Xyzwpr flange = Xyzwpr.fromTransform(ForwardKinematics.flangePoseInWorld(robot, q));
      w.run(t -> SceneSnapshots.singleRobot(robot, q, t),
          (fw, fh) -> RobotStatusPanel.draw("Robot", pendantDeg, flange));
    } catch (GlUnavailableException e) {
      throw new UserError("cannot open the simulator window: " + e.getMessage(), Main.EXIT_FAILED);
    }
    return Main.EXIT_OK;
  }
}
