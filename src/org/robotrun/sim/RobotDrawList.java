package org.robotrun.sim;

import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/** Fills draw items for a robot at given joint values: a link's display meshes, or else one item per link shape. */
public final class RobotDrawList {
  /** FANUC-style yellow, dark joint housings, grey base, bright flange. */
  public static final DrawItem.Color BODY = DrawItem.Color.rgb(0.95, 0.74, 0.06);
  public static final DrawItem.Color JOINT = DrawItem.Color.rgb(0.16, 0.16, 0.18);
  public static final DrawItem.Color BASE = DrawItem.Color.rgb(0.22, 0.22, 0.24);
  public static final DrawItem.Color FLANGE = DrawItem.Color.rgb(0.62, 0.63, 0.66);

  private RobotDrawList() {}

  /**
   * Adds the robot's link bodies, placed by forward kinematics.
   *
   * @param X_WR the robot's WORLD frame in the cell's frame (identity for a single robot)
   * @param q joint values (rad, kinematic convention)
   */
  public static void addRobot(List<DrawItem> out, String prefix, RobotModel model, Transform X_WR, double[] q) {
    addRobot(out, prefix, model, X_WR, ForwardKinematics.linkPosesInWorld(model, q));
  }

  /** As {@link #addRobot(List, String, RobotModel, Transform, double[])} with the link poses in the robot's WORLD already computed. */
  public static void addRobot(List<DrawItem> out, String prefix, RobotModel model, Transform X_WR, Transform[] X_RL) {
    for (int i = 0; i < model.links().size(); i++) {
      LinkSpec link = model.links().get(i);
      Transform X_WL = X_WR.compose(X_RL[i]);
      // Display meshes (imported robots) replace the shapes on screen; the shapes stay the collision bodies.
      for (LinkMesh m : link.meshes()) {
        out.add(new DrawItem(prefix + "/" + link.name(), new DrawShape.Mesh("robot:" + model.id() + "/" + m.key(), m.triangles()),
            X_WL, colorOf(m.color())));
      }
      if (!link.meshes().isEmpty()) {
        continue;
      }
      for (LinkShape s : link.shapes()) {
        out.add(new DrawItem(prefix + "/" + link.name(), shapeOf(s), X_WL.compose(s.X_LS()), colorOf(s.color())));
      }
    }
  }

  static DrawShape shapeOf(LinkShape s) {
    return switch (s) {
      case LinkShape.Box b -> new DrawShape.Box(b.size(), true);
      case LinkShape.Cylinder c -> new DrawShape.Cylinder(c.radius(), c.length());
    };
  }

  /** A colour role, or "#rrggbb" (an imported robot's material colour). */
  static DrawItem.Color colorOf(String name) {
    if (name.length() == 7 && name.charAt(0) == '#') {
      try {
        int rgb = Integer.parseInt(name.substring(1), 16);
        return DrawItem.Color.rgb(((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0);
      } catch (NumberFormatException e) {
        return BODY;
      }
    }
    return switch (name) {
      case "joint" -> JOINT;
      case "base" -> BASE;
      case "flange" -> FLANGE;
      default -> BODY;
    };
  }
}
