package org.robotrun.sim;

import java.util.Locale;
import org.robotrun.collision.Body;
import org.robotrun.collision.BodyKind;

/**
 * A collision body as a student knows it, for alarms, the ALARM screen and reports: the robot's
 * name and its link by the joint that moves it ("robot1 J2 upper arm"), an end-effector box by
 * the tool and the box ("robot1 gripper finger1"), anything else by its scenario name ("table").
 * The collision world's internal ids ("robot1/link2#2") stay in the run report's {@code a}/{@code b}
 * for tools.
 */
public final class BodyNames {
  /**
   * The links as docs/robots.md and scenario-format.md name them, each after the joint that moves
   * it (the pendant's J1..J6): link 0 is the fixed base.
   */
  private static final String[] LINKS = {
      "base", "J1 shoulder", "J2 upper arm", "J3 elbow", "J4 forearm", "J5 wrist", "J6 flange"};

  private BodyNames() {}

  /**
   * The student's name of {@code body}.
   *
   * @param toolType the end effector's type on this robot ("gripper"), "" for the plain tool bar
   */
  public static String of(Body body, String toolType) {
    if (body.kind() != BodyKind.ROBOT) {
      return body.name();
    }
    String robot = body.owner();
    if (body.link() >= 0 && body.link() < LINKS.length) {
      return robot + " " + LINKS[body.link()];
    }
    // the end effector: "robot1/tool" (the bar of a robot without one) or "robot1/tool/finger1"
    String prefix = robot + "/tool/";
    String box = body.name().startsWith(prefix) ? body.name().substring(prefix.length()) : "";
    String tool = toolType.isEmpty() ? "tool" : toolType.toLowerCase(Locale.ROOT);
    return box.isEmpty() ? robot + " " + tool : robot + " " + tool + " " + box;
  }

  /** The name of link {@code link} (0 base … 6), as {@link #of} gives it. */
  public static String link(int link) {
    return LINKS[link];
  }
}
