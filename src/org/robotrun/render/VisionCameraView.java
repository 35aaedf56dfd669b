package org.robotrun.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.robotrun.math.Transform;
import org.robotrun.world.VisionSetup;

/**
 * What a vision camera sees, for OpenGL: the camera frame K looks along +z with image rows along
 * +y (a pinhole camera, {@link VisionSetup.Camera}); OpenGL's eye looks along −z with y up, so the
 * eye frame is K turned half a turn about x. The projection is the camera's vertical field of view
 * and image aspect, so a pixel of the rendered image is the pixel {@link VisionSetup.Camera#project}
 * names.
 */
public final class VisionCameraView {
  /** Nearest and farthest distances drawn (mm). */
  static final float NEAR_MM = 10f;
  static final float FAR_MM = 30000f;

  private VisionCameraView() {}

  /** Projection × view for a camera posed at {@code X_CK} (cell frame). */
  public static Matrix4f viewProjection(VisionSetup.Camera cam, Transform X_CK) {
    Transform X_CE = X_CK.compose(Transform.rotation(1, 0, 0, Math.PI));
    float[] m = new float[16];
    X_CE.inverse().toColumnMajor(m);
    Matrix4f view = new Matrix4f().set(m);
    return new Matrix4f().perspective((float) cam.fovRad(), cam.widthPx() / (float) cam.heightPx(), NEAR_MM, FAR_MM)
        .mul(view);
  }

  /** The camera's position in the cell (mm). */
  public static Vector3f eye(Transform X_CK) {
    return new Vector3f((float) X_CK.x(), (float) X_CK.y(), (float) X_CK.z());
  }
}
