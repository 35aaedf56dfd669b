package org.robotrun.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;

/**
 * A camera that orbits a target point, Z up (WORLD convention). Angles in radians, distances in
 * mm. Mutable: the window's mouse handling changes it; snapshots never hold one.
 */
public final class OrbitCamera {
  public static final float FOV_Y_RAD = (float) Math.toRadians(38);

  private final Vector3f target = new Vector3f();
  private float distance;
  private float yaw;
  private float pitch;
  /** Horizontal shift of the image centre in normalised device units (-1..1); 0 is centred. */
  private float centreShiftNdc;

  public OrbitCamera() {
    reset();
  }

  /** The default view: the arm three-quarters from the front, a little above. */
  public void reset() {
    target.set(200, 0, -20);
    distance = 1650;
    yaw = (float) Math.toRadians(-35);
    pitch = (float) Math.toRadians(22);
  }

  public void set(float tx, float ty, float tz, float distanceMm, float yawRad, float pitchRad) {
    target.set(tx, ty, tz);
    distance = Math.max(50, distanceMm);
    yaw = yawRad;
    pitch = clampPitch(pitchRad);
  }

  /** Turns the view: dx, dy in radians. */
  public void orbit(float dYaw, float dPitch) {
    yaw += dYaw;
    pitch = clampPitch(pitch + dPitch);
  }

  /** Moves the target in the view plane by a fraction of the view height. */
  public void pan(float fx, float fy) {
    float h = 2f * distance * (float) Math.tan(FOV_Y_RAD / 2);
    Vector3f fwd = new Vector3f(target).sub(eye()).normalize();
    Vector3f right = new Vector3f(fwd).cross(0, 0, 1).normalize();
    Vector3f up = new Vector3f(right).cross(fwd).normalize();
    target.add(right.mul(-fx * h)).add(up.mul(fy * h));
  }

  /** Zooms by a factor (&lt; 1 moves closer). */
  public void zoom(float factor) {
    distance = Math.max(50, Math.min(40000, distance * factor));
  }

  /** Distance from the target (mm). */
  public float distance() {
    return distance;
  }

  /** Turn about the cell's z axis (rad). */
  public float yaw() {
    return yaw;
  }

  /** Elevation, positive looking down (rad). */
  public float pitch() {
    return pitch;
  }

  public Vector3f eye() {
    float cp = (float) Math.cos(pitch);
    return new Vector3f(
        target.x + distance * cp * (float) Math.cos(yaw),
        target.y + distance * cp * (float) Math.sin(yaw),
        target.z + distance * (float) Math.sin(pitch));
  }

  /**
   * Moves the point the camera looks at away from the image centre, e.g. to the middle of the
   * part of the window a side panel leaves free: -0.4 puts it 20% of the width left of centre.
   */
  public void setCentreShift(float ndc) {
    centreShiftNdc = Math.max(-1f, Math.min(1f, ndc));
  }

  /** The point the camera orbits and looks at (mm); a copy. */
  public Vector3f target() {
    return new Vector3f(target);
  }

  /** Projection times view for a viewport of the given aspect ratio. */
  public Matrix4f viewProjection(float aspect) {
    Vector3f eye = eye();
    return new Matrix4f()
        .translation(centreShiftNdc, 0, 0)
        .perspective(FOV_Y_RAD, aspect, Math.max(1f, distance / 200f), distance * 20f + 20000f)
        .lookAt(eye.x, eye.y, eye.z, target.x, target.y, target.z, 0, 0, 1);
  }

  private static float clampPitch(float p) {
    float lim = (float) Math.toRadians(89);
    return Math.max(-lim, Math.min(lim, p));
  }
}
