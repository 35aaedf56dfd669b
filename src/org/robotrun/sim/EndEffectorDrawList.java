package org.robotrun.sim;

import static org.robotrun.world.EndEffectorGeometry.*;

import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Draw items for an end effector on a flange at {@code X_CF}: the tool's display shapes (the
 * gripper's fingers where they are now) and a process tool's trace. Shapes follow the
 * dimensions of {@link org.robotrun.world.EndEffectorGeometry}; names start with the robot's
 * ("robot1/tool/finger1", "robot1/trace").
 */
final class EndEffectorDrawList {
  static final DrawItem.Color DARK = DrawItem.Color.rgb(0.20, 0.21, 0.23);
  static final DrawItem.Color METAL = DrawItem.Color.rgb(0.70, 0.72, 0.75);
  static final DrawItem.Color RUBBER = DrawItem.Color.rgb(0.08, 0.08, 0.09);
  static final DrawItem.Color TIP = DrawItem.Color.rgb(0.85, 0.20, 0.15);
  static final DrawItem.Color GUN = DrawItem.Color.rgb(0.18, 0.40, 0.70);
  static final DrawItem.Color BEAD = DrawItem.Color.rgb(0.95, 0.80, 0.30);
  /** Trace bead: a short cylinder every {@link #BEAD_SPACING_MM} along the path. */
  static final DrawShape BEAD_SHAPE = new DrawShape.Cylinder(1.5, 3.0);
  static final double BEAD_SPACING_MM = 2;
  /** Length of the pointer's conical tip (mm). */
  static final double POINTER_CONE_MM = 12;
  private static final DrawShape POINTER_CONE = cone("pointer-cone", POINTER_ROD_RADIUS_MM, POINTER_CONE_MM, 24);

  private EndEffectorDrawList() {}

  static void add(List<DrawItem> out, EndEffectorState s, Transform X_CF) {
    String p = s.robot + "/tool";
    switch (s.geometry.type()) {
      case FACEPLATE -> {
      }
      case GRIPPER -> {
        double bodyLen = GRIPPER_BODY_END_MM - FLANGE_GAP_MM;
        out.add(new DrawItem(p + "/body", new DrawShape.Box(new Vec3(GRIPPER_BODY_X_MM, GRIPPER_BODY_Y_MM, bodyLen), true),
            X_CF.compose(Transform.translation(0, 0, FLANGE_GAP_MM + bodyLen / 2)), DARK));
        // A flange plate between the wrist and the body.
        out.add(new DrawItem(p + "/plate", new DrawShape.Cylinder(28, FLANGE_GAP_MM),
            X_CF.compose(Transform.translation(0, 0, FLANGE_GAP_MM / 2)), METAL));
        int k = 1;
        for (var f : s.geometry.fingerBoxes(s.fingerGapMm())) {
          out.add(new DrawItem(p + "/finger" + k++, new DrawShape.Box(new Vec3(2 * f.hxMm(), 2 * f.hyMm(), 2 * f.hzMm()), false),
              X_CF.compose(f.X_LB()), METAL));
        }
      }
      case SUCTION -> {
        double stem = SUCTION_CUP_START_MM - FLANGE_GAP_MM;
        out.add(new DrawItem(p + "/stem", new DrawShape.Cylinder(SUCTION_STEM_RADIUS_MM, stem),
            X_CF.compose(Transform.translation(0, 0, FLANGE_GAP_MM + stem / 2)), METAL));
        double cup = SUCTION_TCP_MM - SUCTION_CUP_START_MM;
        out.add(new DrawItem(p + "/cup", new DrawShape.Cylinder(SUCTION_CUP_RADIUS_MM, cup),
            X_CF.compose(Transform.translation(0, 0, SUCTION_CUP_START_MM + cup / 2)), s.on() ? TIP : RUBBER));
      }
      case POINTER -> {
        double holder = POINTER_HOLDER_END_MM - FLANGE_GAP_MM;
        out.add(new DrawItem(p + "/holder", new DrawShape.Cylinder(POINTER_HOLDER_RADIUS_MM, holder),
            X_CF.compose(Transform.translation(0, 0, FLANGE_GAP_MM + holder / 2)), DARK));
        double rod = POINTER_TCP_MM - POINTER_CONE_MM - POINTER_HOLDER_END_MM;
        out.add(new DrawItem(p + "/rod", new DrawShape.Cylinder(POINTER_ROD_RADIUS_MM, rod),
            X_CF.compose(Transform.translation(0, 0, POINTER_HOLDER_END_MM + rod / 2)), METAL));
        out.add(new DrawItem(p + "/tip", POINTER_CONE,
            X_CF.compose(Transform.translation(0, 0, POINTER_TCP_MM - POINTER_CONE_MM)), TIP));
      }
      case GLUEGUN -> {
        double body = GLUE_BODY_END_MM - FLANGE_GAP_MM;
        out.add(new DrawItem(p + "/body", new DrawShape.Box(new Vec3(GLUE_BODY_MM, GLUE_BODY_MM, body), true),
            X_CF.compose(Transform.translation(0, 0, FLANGE_GAP_MM + body / 2)), GUN));
        double nozzle = GLUE_TCP_MM - GLUE_BODY_END_MM;
        out.add(new DrawItem(p + "/nozzle", new DrawShape.Cylinder(GLUE_NOZZLE_RADIUS_MM, nozzle),
            X_CF.compose(Transform.translation(0, 0, GLUE_BODY_END_MM + nozzle / 2)), s.on() ? BEAD : METAL));
        addTrace(out, s.robot + "/trace", s.trace());
      }
    }
  }

  /** Beads along each segment, no more than {@link #BEAD_SPACING_MM} apart. */
  static void addTrace(List<DrawItem> out, String name, List<EndEffectorState.TraceSegment> trace) {
    for (EndEffectorState.TraceSegment seg : trace) {
      Vec3 d = seg.to().minus(seg.from());
      double len = d.norm();
      if (len < 1e-9) {
        continue;
      }
      Transform R = alongZ(d.times(1 / len));
      int n = (int) Math.ceil(len / BEAD_SPACING_MM);
      for (int i = 0; i < n; i++) {
        Vec3 c = seg.from().plus(d.times((i + 0.5) / n));
        out.add(new DrawItem(name, BEAD_SHAPE, R.withTranslation(c.x(), c.y(), c.z()), BEAD));
      }
    }
  }

  /** A rotation taking z onto the unit vector {@code d}. */
  static Transform alongZ(Vec3 d) {
    Vec3 axis = Vec3.Z.cross(d);
    double s = axis.norm();
    double c = Vec3.Z.dot(d);
    if (s < 1e-12) {
      return c > 0 ? Transform.IDENTITY : Transform.rotation(1, 0, 0, Math.PI);
    }
    return Transform.rotation(axis.x() / s, axis.y() / s, axis.z() / s, Math.atan2(s, c));
  }

  /** A cone with its base (radius {@code r}) at z = 0 and its point at z = {@code h}. */
  static DrawShape.Mesh cone(String key, double r, double h, int segments) {
    float[] t = new float[segments * 2 * 9];
    int o = 0;
    for (int i = 0; i < segments; i++) {
      double a0 = 2 * Math.PI * i / segments;
      double a1 = 2 * Math.PI * (i + 1) / segments;
      float x0 = (float) (r * Math.cos(a0)), y0 = (float) (r * Math.sin(a0));
      float x1 = (float) (r * Math.cos(a1)), y1 = (float) (r * Math.sin(a1));
      // Side (counter-clockwise seen from outside), then the base facing -z.
      float[] side = {x0, y0, 0, x1, y1, 0, 0, 0, (float) h};
      float[] base = {0, 0, 0, x1, y1, 0, x0, y0, 0};
      System.arraycopy(side, 0, t, o, 9);
      System.arraycopy(base, 0, t, o + 9, 9);
      o += 18;
    }
    return new DrawShape.Mesh(key, t);
  }
}
