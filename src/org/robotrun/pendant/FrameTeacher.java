package org.robotrun.pendant;

import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.pendant.RobotControl.TeachMethod;
import org.robotrun.pendant.RobotControl.TeachResult;

/**
 * Frame teaching geometry for a controller that has none of its own: the project's lives in
 * {@code robot.FrameTeaching}, which the pendant may not import, so the application passes it
 * in (see {@code app.RobotFrameTeacher}).
 */
@FunctionalInterface
public interface FrameTeacher {
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
