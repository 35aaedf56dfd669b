package org.robotrun.sim;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.robotrun.collision.Body;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.LocalBox;
import org.robotrun.world.RobotBodies;
import org.robotrun.world.World;
import org.robotrun.world.WorldBodies;

/**
 * Collision checking of a cell, once per tick: every robot's link bodies (a box around each link
 * shape) and its active tool (a 20 mm square bar from the flange to the TCP), and the world's
 * fixtures and parts, under the {@link StandardPairFilter} rules (self-collision of links at
 * least two apart, robot against fixtures, parts and other robots). Reports the contacts that
 * began at this tick, so a lasting contact raises one alarm, not one per tick.
 *
 * <p>The tool bar is rebuilt when a robot's active tool changes (rare). Not thread-safe.
 */
final class CellCollisions {
  /** Cross-section of the tool bar (mm). */
  static final double TOOL_BAR_MM = 20;
  /** Gap left between the flange and the tool bar so the bar does not touch the wrist (mm). */
  static final double TOOL_GAP_MM = 2;

  private final List<Controller> controllers;
  private final List<Transform> X_CW;
  private final World world;
  private CollisionWorld collision;
  private List<RobotBodies> robots;
  private Transform[] tools;
  private final Transform[] X_CL = new Transform[Body.TOOL_LINK + 1];
  private final LinkPoses[] poses;
  /** Joints at the last check, per robot: nothing moved, nothing new to find. */
  private final double[][] lastQ;
  private Set<String> touching = new HashSet<>();

  /** A contact that began: the two bodies' names ("robot1/link5", "table"). */
  record NewContact(String a, String aOwner, String b, String bOwner) {}

  CellCollisions(List<Controller> controllers, List<Transform> X_CW, World world) {
    this.controllers = controllers;
    this.X_CW = X_CW;
    this.world = world;
    this.poses = new LinkPoses[controllers.size()];
    this.lastQ = new double[controllers.size()][];
    for (int r = 0; r < controllers.size(); r++) {
      poses[r] = new LinkPoses(controllers.get(r).model(), X_CW.get(r));
    }
    build();
  }

  private void build() {
    collision = new CollisionWorld(new CellPairFilter(StandardPairFilter.nothingHeld()));
    new WorldBodies(world, collision);
    robots = new ArrayList<>();
    tools = new Transform[controllers.size()];
    for (int r = 0; r < controllers.size(); r++) {
      Controller c = controllers.get(r);
      tools[r] = c.frames().activeTool();
      robots.add(new RobotBodies(c.name(), boxes(c.model(), tools[r]), collision));
    }
  }

  /** Boxes per link 0..6 from the link shapes, and link 7 (tool) from the flange to the TCP. */
  static List<List<LocalBox>> boxes(RobotModel model, Transform X_FT) {
    List<List<LocalBox>> out = new ArrayList<>();
    for (var link : model.links()) {
      List<LocalBox> boxes = new ArrayList<>();
      for (LinkShape s : link.shapes()) {
        boxes.add(switch (s) {
          case LinkShape.Box b -> LocalBox.ofBox(b.X_LS(), b.size());
          case LinkShape.Cylinder cy -> LocalBox.ofCylinder(cy.X_LS(), cy.radius(), cy.length());
        });
      }
      out.add(boxes);
    }
    List<LocalBox> tool = new ArrayList<>();
    Vec3 p = X_FT.translationVector();
    double length = p.norm() - TOOL_GAP_MM;
    if (length > 1) {
      // A bar along the flange-to-TCP line, centred half-way past the gap.
      Vec3 dir = p.normalized();
      Vec3 centre = dir.times(TOOL_GAP_MM + length / 2);
      Transform X_FB = alongZ(dir).withTranslation(centre.x(), centre.y(), centre.z());
      tool.add(new LocalBox(X_FB, TOOL_BAR_MM / 2, TOOL_BAR_MM / 2, length / 2));
    }
    out.add(tool);
    return out;
  }

  /** A rotation taking z onto the unit vector {@code d}. */
  private static Transform alongZ(Vec3 d) {
    Vec3 axis = Vec3.Z.cross(d);
    double s = axis.norm();
    double c = Vec3.Z.dot(d);
    if (s < 1e-12) {
      return c > 0 ? Transform.IDENTITY : Transform.rotation(1, 0, 0, Math.PI);
    }
    return Transform.rotation(axis.x() / s, axis.y() / s, axis.z() / s, Math.atan2(s, c));
  }

  /** Moves every robot's bodies to its current joints, runs the check, returns contacts that began now. */
  List<NewContact> check() {
    boolean rebuilt = false;
    for (int r = 0; r < controllers.size(); r++) {
      if (!controllers.get(r).frames().activeTool().equals(tools[r])) {
        build();
        touching = new HashSet<>();
        java.util.Arrays.fill(lastQ, null);
        rebuilt = true;
        break;
      }
    }
    boolean moved = rebuilt;
    for (int r = 0; r < controllers.size(); r++) {
      double[] q = controllers.get(r).jointsRad();
      if (lastQ[r] != null && java.util.Arrays.equals(q, lastQ[r])) {
        continue;
      }
      lastQ[r] = q;
      moved = true;
      poses[r].compute(q, X_CL);
      robots.get(r).moveTo(X_CL, collision);
    }
    if (!moved) {
      return List.of();
    }
    int n = collision.update();
    if (n == 0 && touching.isEmpty()) {
      return List.of();
    }
    Set<String> now = new HashSet<>();
    List<NewContact> began = new ArrayList<>();
    for (var contact : collision.contacts()) {
      String key = contact.a().name() + "|" + contact.b().name();
      now.add(key);
      if (!touching.contains(key)) {
        began.add(new NewContact(contact.a().name(), contact.a().owner(), contact.b().name(), contact.b().owner()));
      }
    }
    touching = now;
    return began;
  }
}
