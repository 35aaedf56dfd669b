package org.robotrun.app;

import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Angles;
import org.robotrun.math.Xyzwpr;
import org.robotrun.pendant.Pendant;
import org.robotrun.pendant.StandInRobotControl;
import org.robotrun.program.Position;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshots;
import org.robotrun.ui.PendantKeyboard;
import org.robotrun.ui.PendantPanel;
import org.robotrun.ui.RobotStatusPanel;
import org.robotrun.ui.SimulatorWindow;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun gui} (also what {@code robotrun} alone does): the simulator window. */
@Command(
    name = "gui",
    mixinStandardHelpOptions = true,
    description = {
      "Open the simulator window (what 'robotrun' with no subcommand does): the cell in 3D and the teach pendant.",
      "Mouse: left drag orbits, right or middle drag pans, wheel zooms; Home resets the view.",
      "Pendant keys are buttons on the pendant panel and keys on the keyboard (docs/user-guide.md): Shift is the deadman, Q..Y jog +J1..+J6 (+X..+ZR), A..H jog -J1..-J6, arrows move the cursor, F1-F5 the function keys."
    })
public final class GuiCommand implements Callable<Integer> {
  @Option(names = "--width", defaultValue = "1280", description = "Window width (default: ${DEFAULT-VALUE}).")
  int width = 1280;

  @Option(names = "--height", defaultValue = "800", description = "Window height (default: ${DEFAULT-VALUE}).")
  int height = 800;

  @Override
  public Integer call() {
    RenderCommand.checkSize("--width", width);
    RenderCommand.checkSize("--height", height);
    RobotModel robot = RobotDefinitions.defaultRobot();
    Pendant pendant = new Pendant(new StandInRobotControl());
    PendantPanel pendantPanel = new PendantPanel(pendant);
    try (SimulatorWindow w = new SimulatorWindow("RobotRun — " + robot.displayName(), width, height)) {
      w.setKeyHandler(new PendantKeyboard(pendant)::onKey);
      double[] last = {0};
      w.run(t -> {
            pendant.advance(Math.min(0.1, t - last[0]));
            last[0] = t;
            return SceneSnapshots.singleRobot(robot, kinematicJoints(robot, pendant), t);
          },
          (fw, fh) -> {
            double[] q = kinematicJoints(robot, pendant);
            RobotStatusPanel.draw("Robot", Angles.toDegrees(JointConvention.kinematicToPendant(robot, q)),
                Xyzwpr.fromTransform(ForwardKinematics.flangePoseInWorld(robot, q)));
            pendantPanel.draw(fw, fh);
          });
    } catch (GlUnavailableException e) {
      throw new UserError("cannot open the simulator window: " + e.getMessage(), Main.EXIT_FAILED);
    }
    return Main.EXIT_OK;
  }

  /** The controller's joints (pendant degrees) as kinematic radians. */
  private static double[] kinematicJoints(RobotModel robot, Pendant pendant) {
    Position.Joint j = pendant.control().currentJoints();
    double[] deg = new double[RobotModel.DOF];
    for (int i = 0; i < deg.length; i++) {
      deg[i] = j.element(i + 1);
    }
    return JointConvention.pendantToKinematic(robot, Angles.toRadians(deg));
  }
}
