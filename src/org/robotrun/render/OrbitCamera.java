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
  /**
   * The part of the framebuffer the scene is framed in (pixels, GL's bottom-left origin): the
   * area the window's panels leave free. Width 0: the whole framebuffer.
   */
  private int viewX;
  private int viewY;
  private int viewW;
  private int viewH;

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

  /**
   * Frames the scene in a part of the framebuffer (pixels, bottom-left origin): the projection
   * uses that rectangle's aspect and centres on it, so a side panel never hides the middle of the
   * view. {@code w <= 0} uses the whole framebuffer.
   */
  public void setViewRect(int x, int y, int w, int h) {
    viewX = x;
    viewY = y;
    viewW = Math.max(0, w);
    viewH = Math.max(0, h);
  }

  /** The free rectangle of {@link #setViewRect} clipped to a framebuffer: {x, y, w, h} (pixels). */
  public int[] viewRect(int framebufferWidth, int framebufferHeight) {
    if (viewW <= 0 || viewH <= 0) {
      return new int[] {0, 0, framebufferWidth, framebufferHeight};
    }
    int x = Math.max(0, Math.min(viewX, framebufferWidth - 1));
    int y = Math.max(0, Math.min(viewY, framebufferHeight - 1));
    return new int[] {x, y, Math.max(1, Math.min(viewW, framebufferWidth - x)), Math.max(1, Math.min(viewH, framebufferHeight - y))};
  }

  /**
   * Projection times view for a whole framebuffer of the given size, the scene framed in the
   * rectangle of {@link #setViewRect}: a perspective for that rectangle's aspect, then scaled and
   * moved in normalised device coordinates onto it.
   */
  public Matrix4f viewProjection(int framebufferWidth, int framebufferHeight) {
    int[] r = viewRect(framebufferWidth, framebufferHeight);
    float fw = Math.max(1, framebufferWidth), fh = Math.max(1, framebufferHeight);
    float sx = r[2] / fw, sy = r[3] / fh;
    float tx = (2f * r[0] + r[2]) / fw - 1f, ty = (2f * r[1] + r[3]) / fh - 1f;
    Vector3f eye = eye();
    return new Matrix4f()
        .translation(tx + centreShiftNdc * sx, ty, 0)
        .scale(sx, sy, 1)
        .perspective(FOV_Y_RAD, r[2] / (float) r[3], Math.max(1f, distance / 200f), distance * 20f + 20000f)
        .lookAt(eye.x, eye.y, eye.z, target.x, target.y, target.z, 0, 0, 1);
  }

  /**
   * Moves the camera back or forward along its line of sight so every point lies inside the
   * view of the given aspect (width/height), with {@code margin} (e.g. 0.1) of the half-extent
   * to spare; keeps the direction and target.
   */
  public void fitDistance(Iterable<Vector3f> pointsMm, float aspect, float margin) {
    Vector3f eye = eye();
    Vector3f fwd = new Vector3f(target).sub(eye).normalize();
    Vector3f right = new Vector3f(fwd).cross(0, 0, 1).normalize();
    Vector3f up = new Vector3f(right).cross(fwd).normalize();
    float tanY = (float) Math.tan(FOV_Y_RAD / 2) * (1 - margin);
    float tanX = tanY * aspect;
    float need = 50;
    Vector3f d = new Vector3f();
    for (Vector3f p : pointsMm) {
      d.set(p).sub(target);
      float along = d.dot(fwd);
      // distance from the target at which the point's offset fits the half-angle
      need = Math.max(need, Math.abs(d.dot(right)) / tanX - along);
      need = Math.max(need, Math.abs(d.dot(up)) / tanY - along);
    }
    distance = Math.min(40000, need);
  }

  public float yaw() {
    return yaw;
  }

  public float pitch() {
    return pitch;
  }

  /** Distance from the target to the eye (mm). */
  public float distance() {
    return distance;
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
