package org.robotrun.sim;

import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.robot.RobotModel;

/**
 * The cell used when no scenario is given: one robot named "robot1" at HOME (J5 = −90°, the
 * tool pointing down), UTOOL[1] a 100 mm pointer along the flange's z axis, UFRAME[1] equal to
 * WORLD, both selected.
 */
public final class DefaultCell {
  /** HOME: all joints 0 except J5 = −90° (pendant degrees). */
  public static final Position.Joint HOME = new Position.Joint(0, 0, 0, 0, -90, 0);
  /** Length of the default pointer tool (mm). */
  public static final double POINTER_MM = 100;

  private DefaultCell() {}

  /** A controller set up as described above. */
  public static Controller controller(RobotModel model) {
    return controller(model, "robot1");
  }

  /** A controller set up as described above, named {@code name}. */
  public static Controller controller(RobotModel model, String name) {
    Controller c = new Controller(name, model, HOME);
    c.frames().setTransform(FrameKind.TOOL, 1, Transform.translation(0, 0, POINTER_MM));
    c.frames().setComment(FrameKind.TOOL, 1, "pointer 100 mm");
    c.frames().setTransform(FrameKind.USER, 1, Transform.IDENTITY);
    c.frames().setComment(FrameKind.USER, 1, "world");
    c.frames().select(FrameKind.TOOL, 1);
    c.frames().select(FrameKind.USER, 1);
    return c;
  }

  /** The default cell's simulation (4 ms ticks). */
  public static Simulation simulation(RobotModel model) {
    return Simulation.of(controller(model));
  }
}
