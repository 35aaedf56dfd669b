package org.robotrun.pendant;

import java.util.List;
import org.robotrun.control.RobotControl.TeachMethod;
import org.robotrun.control.RobotControl.TeachResult;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Frame teaching geometry for the stand-in controller, which has none of its own: the project's is
 * {@code sim.RobotFrameTeacher} (over {@code robot.FrameTeaching}), passed in by {@link StandIn}.
 */
@FunctionalInterface
interface FrameTeacher {
  /**
   * Computes the frame a method's recorded points define.
   *
   * @param flanges X_WF, the flange pose in WORLD at each recorded point (tool methods)
   * @param tcps p_W, the active tool's TCP in WORLD at each recorded point (user methods)
   * @return the frame (X_FT for a tool, X_WU for a user frame) or why the points do not define one
   */
  TeachResult teach(TeachMethod method, List<Transform> flanges, List<Vec3> tcps);

  /** No teaching: every method answers that it is not available. */
  FrameTeacher NONE = (method, flanges, tcps) ->
      new TeachResult.Failed("frame teaching is not available on this controller");
}
