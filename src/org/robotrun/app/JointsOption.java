package org.robotrun.app;

import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;

/** Parses a {@code --joints j1,...,j6} value: degrees, pendant convention (coupled J3). */
final class JointsOption {
  private JointsOption() {}

  /**
   * Returns kinematic joint values (rad) for the text, or throws a {@link UserError} naming what
   * is wrong: the count, a value that is not a number, or a joint outside its limits.
   */
  static double[] parseToKinematic(String text, RobotModel model) {
    String[] parts = text.split(",", -1);
    if (parts.length != RobotModel.DOF) {
      throw new UserError("--joints: expected 6 comma-separated angles in degrees (j1,...,j6), got "
          + parts.length + " value" + (parts.length == 1 ? "" : "s") + " in '" + text + "'");
    }
    double[] pendantRad = new double[RobotModel.DOF];
    for (int i = 0; i < parts.length; i++) {
      double deg;
      try {
        deg = Double.parseDouble(parts[i].trim());
      } catch (NumberFormatException e) {
        throw new UserError("--joints: J" + (i + 1) + " is not a number: '" + parts[i].trim() + "'");
      }
      if (!Double.isFinite(deg)) {
        throw new UserError("--joints: J" + (i + 1) + " must be a finite number of degrees, got '" + parts[i].trim() + "'");
      }
      pendantRad[i] = Math.toRadians(deg);
    }
    double[] q = JointConvention.pendantToKinematic(model, pendantRad);
    int bad = model.firstJointOutsideLimits(q);
    if (bad >= 0) {
      var j = model.joint(bad);
      String coupled = bad == 2 && model.coupledJ3() ? " (J3 is coupled: J3 + J2 must lie in the range)" : "";
      throw new UserError(String.format(java.util.Locale.ROOT, "--joints: J%d is outside its limits %.0f..%.0f deg%s",
          bad + 1, Math.toDegrees(j.lowerRad()), Math.toDegrees(j.upperRad()), coupled));
    }
    return q;
  }
}
