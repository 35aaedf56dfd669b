package org.robotrun.world;

import org.robotrun.math.Vec3;

/**
 * An orbit camera: it looks at {@code targetMm} from {@code distanceMm} away, turned by
 * {@code yawRad} about the cell's z axis (0 = looking along +x) and raised by {@code pitchRad}
 * (positive = looking down).
 */
public record CameraView(Vec3 targetMm, double distanceMm, double yawRad, double pitchRad) {
  public CameraView {
    if (!(distanceMm > 0)) {
      throw new IllegalArgumentException("camera distance must be > 0, got " + distanceMm);
    }
  }
}
