package org.robotrun.world;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.collision.Body;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.math.Transform;

/**
 * The collision boxes of one robot in a {@link CollisionWorld}: a few {@link LocalBox}es per
 * link (index 0 = base … 6 = link 6, then optionally {@link Body#TOOL_LINK} for the end
 * effector), moved each tick from the links' poses without allocating.
 *
 * <p>World may not see the robot package, so the simulation turns the robot's link shapes
 * into local boxes ({@link LocalBox#ofBox}, {@link LocalBox#ofCylinder}) and passes them here.
 */
public final class RobotBodies {
  private final int[] handles;
  private final int[] linkOf;
  private final Transform[] X_LB;

  /**
   * Adds the robot's boxes to {@code collision}, all at the identity until the first
   * {@link #moveTo}.
   *
   * @param robot owner name, e.g. "robot1"; bodies are named "robot1/link3", "robot1/tool#1"
   * @param boxesPerLink entry i holds the boxes of link i (i = 7 for the end effector)
   */
  public RobotBodies(String robot, List<List<LocalBox>> boxesPerLink, CollisionWorld collision) {
    List<Integer> h = new ArrayList<>();
    List<Integer> l = new ArrayList<>();
    List<Transform> x = new ArrayList<>();
    for (int link = 0; link < boxesPerLink.size(); link++) {
      List<LocalBox> boxes = boxesPerLink.get(link);
      for (int k = 0; k < boxes.size(); k++) {
        LocalBox b = boxes.get(k);
        String linkName = link == Body.TOOL_LINK ? "tool" : link == 0 ? "base" : "link" + link;
        String name = robot + "/" + linkName + (boxes.size() > 1 ? "#" + (k + 1) : "");
        h.add(collision.add(Body.robotLink(robot, link, name), b.inWorld(Transform.IDENTITY)));
        l.add(link);
        x.add(b.X_LB());
      }
    }
    handles = h.stream().mapToInt(Integer::intValue).toArray();
    linkOf = l.stream().mapToInt(Integer::intValue).toArray();
    X_LB = x.toArray(Transform[]::new);
  }

  /** Number of boxes. */
  public int size() {
    return handles.length;
  }

  /** Handle of box {@code k} in the collision world. */
  public int handle(int k) {
    return handles[k];
  }

  /** Moves every box to its link's pose: {@code X_WL[i]} is link i in WORLD (cell) frame. */
  public void moveTo(Transform[] X_WL, CollisionWorld collision) {
    for (int k = 0; k < handles.length; k++) {
      collision.setPose(handles[k], X_WL[linkOf[k]], X_LB[k]);
    }
  }
}
