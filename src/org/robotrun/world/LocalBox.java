package org.robotrun.world;

import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * A box fixed in a moving frame L (an object, a robot link, a tool): its pose {@code X_LB} and
 * half extents (mm). Robot link boxes are built from the robot's link shapes by the
 * simulation (which may see the robot package) with {@link #ofBox} and {@link #ofCylinder}.
 */
public record LocalBox(Transform X_LB, double hxMm, double hyMm, double hzMm) {
  public LocalBox {
    if (!(hxMm >= 0 && hyMm >= 0 && hzMm >= 0)) {
      throw new IllegalArgumentException("half extents must be >= 0");
    }
  }

  /** A box shape centred at {@code X_LS} with full edge lengths {@code sizeMm}. */
  public static LocalBox ofBox(Transform X_LS, Vec3 sizeMm) {
    return new LocalBox(X_LS, sizeMm.x() / 2, sizeMm.y() / 2, sizeMm.z() / 2);
  }

  /** The box around a cylinder centred at {@code X_LS}, axis along its z. */
  public static LocalBox ofCylinder(Transform X_LS, double radiusMm, double lengthMm) {
    return new LocalBox(X_LS, radiusMm, radiusMm, lengthMm / 2);
  }

  /** This box in W when its frame L is at {@code X_WL}. */
  public Obb inWorld(Transform X_WL) {
    return Obb.of(X_WL.compose(X_LB), hxMm, hyMm, hzMm);
  }
}
