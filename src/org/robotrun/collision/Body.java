package org.robotrun.collision;

/**
 * Identity of one collision box: a readable name for alarms ("robot1/link3", "table"), the
 * owner the box belongs to (a robot, a fixture or a part: all boxes of one owner share it), its
 * kind, and for robot boxes the link index (0 = base … 6 = link 6, {@link #TOOL_LINK} = end
 * effector; {@code -1} for everything else).
 */
public record Body(String name, String owner, BodyKind kind, int link) {
  /** Link index used for end-effector boxes; it is adjacent to link 6. */
  public static final int TOOL_LINK = 7;

  public Body {
    if (name == null || owner == null || kind == null) {
      throw new IllegalArgumentException("a body needs a name, an owner and a kind");
    }
    if ((kind == BodyKind.ROBOT) != (link >= 0)) {
      throw new IllegalArgumentException("robot boxes need a link index >= 0, others -1: " + name);
    }
  }

  /** A robot box on link {@code link} of robot {@code robot}. */
  public static Body robotLink(String robot, int link, String name) {
    return new Body(name, robot, BodyKind.ROBOT, link);
  }

  /** A box of a fixture. */
  public static Body fixture(String owner, String name) {
    return new Body(name, owner, BodyKind.FIXTURE, -1);
  }

  /** A box of a part. */
  public static Body part(String owner, String name) {
    return new Body(name, owner, BodyKind.PART, -1);
  }
}
