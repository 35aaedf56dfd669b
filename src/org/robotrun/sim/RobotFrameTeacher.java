package org.robotrun.sim;

import java.util.List;
import org.robotrun.control.RobotControl.TeachMethod;
import org.robotrun.control.RobotControl.TeachResult;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Config;
import org.robotrun.program.Position;
import org.robotrun.robot.FrameTeaching;
import org.robotrun.robot.FrameTeachingException;

/** The pendant's frame teaching done by {@link FrameTeaching} (the kinematics issue's methods). */
public final class RobotFrameTeacher {
  /**
   * Computes the frame a method's recorded points define.
   *
   * @param X_WF the flange pose in WORLD at each recorded point (tool methods)
   * @param p_W the active tool's TCP in WORLD at each recorded point (user methods)
   * @return the frame (X_FT for a tool, X_WU for a user frame) or why the points do not define one
   */
  public TeachResult teach(TeachMethod method, List<Transform> X_WF, List<Vec3> p_W) {
    Transform frame;
    try {
      frame = switch (method) {
        case TOOL_THREE_POINT -> FrameTeaching.toolThreePoint(X_WF);
        case TOOL_SIX_POINT_XZ, TOOL_SIX_POINT_XY -> FrameTeaching.toolSixPoint(X_WF.subList(0, 3), X_WF.get(3),
            X_WF.get(4), X_WF.get(5), method == TeachMethod.TOOL_SIX_POINT_XZ
                ? FrameTeaching.SixPointVariant.XZ : FrameTeaching.SixPointVariant.XY);
        case USER_THREE_POINT -> FrameTeaching.userThreePoint(p_W.get(0), p_W.get(1), p_W.get(2));
        case USER_FOUR_POINT -> FrameTeaching.userFourPoint(p_W.get(0), p_W.get(1), p_W.get(2), p_W.get(3));
        case DIRECT_ENTRY_TOOL, DIRECT_ENTRY_USER -> throw new FrameTeachingException("-", "direct entry has no points");
      };
    } catch (FrameTeachingException e) {
      return new TeachResult.Failed(e.getMessage());
    }
    return new TeachResult.Taught(Position.Cartesian.of(Xyzwpr.fromTransform(frame), Config.DEFAULT), "");
  }
}
