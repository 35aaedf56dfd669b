package org.robotrun.collision;

import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * The rules a robot cell uses, as a value: make a new one when a grip changes.
 *
 * <ul>
 *   <li>Boxes of one robot: links at least two apart are checked (self-collision); a link and
 *       its neighbours, and boxes of the same link, are not. The end effector counts as link
 *       {@link Body#TOOL_LINK}, adjacent to link 6.
 *   <li>Boxes of one fixture or one part never collide with each other.
 *   <li>Objects at rest (fixtures and parts not held) are not checked against each other:
 *       parts lie on fixtures, fixtures stand on each other, and nothing moves them.
 *   <li>A robot's base (link 0) is not checked against fixtures: it stands on one.
 *   <li>A held part is not checked against the robot holding it (and {@code gripping} parts,
 *       the ones being gripped right now, likewise), but is checked against everything else.
 *   <li>Everything else is checked: robot against fixtures, parts and other robots.
 *   <li>Except the {@code allowedContacts}: pairs that touch by construction. Link boxes are
 *       coarse, and on a compact arm the upper arm's elbow box overlaps the forearm's (links
 *       2 and 4 of the LR Mate) in every pose; like a controller's interference model (or
 *       MoveIt's "default" disabled collisions) such pairs are found once at a reference pose
 *       ({@link #robotSelfContacts}) and ignored from then on.
 * </ul>
 *
 * @param holderByPart owner name of each held or gripped part → owner name of the robot
 * @param allowedContacts body pairs never reported
 */
public record StandardPairFilter(Map<String, String> holderByPart, Set<BodyPair> allowedContacts) implements PairFilter {

  public StandardPairFilter {
    holderByPart = Map.copyOf(holderByPart);
    allowedContacts = Set.copyOf(allowedContacts);
  }

  /** The rules with these held parts and no allowed contacts. */
  public StandardPairFilter(Map<String, String> holderByPart) {
    this(holderByPart, Set.of());
  }

  /** The same rules with other held parts (the allowed contacts stay). */
  public StandardPairFilter withHeld(Map<String, String> holderByPart) {
    return new StandardPairFilter(holderByPart, allowedContacts);
  }

  /** The same rules, also ignoring {@code pairs}. */
  public StandardPairFilter withAllowedContacts(Set<BodyPair> pairs) {
    return new StandardPairFilter(holderByPart, pairs);
  }

  /** The contacts between boxes of one robot among {@code contacts}, as name pairs. */
  public static Set<BodyPair> robotSelfContacts(List<Contact> contacts) {
    return contacts.stream()
        .filter(c -> c.a().kind() == BodyKind.ROBOT && c.a().owner().equals(c.b().owner()))
        .map(c -> BodyPair.of(c.a(), c.b()))
        .collect(Collectors.toUnmodifiableSet());
  }

  /** The rules with no part held. */
  public static StandardPairFilter nothingHeld() {
    return new StandardPairFilter(Map.of());
  }

  @Override
  public boolean mayCollide(Body a, Body b) {
    if (!allowedContacts.isEmpty() && allowedContacts.contains(BodyPair.of(a, b))) {
      return false;
    }
    if (a.owner().equals(b.owner())) {
      return a.kind() == BodyKind.ROBOT && Math.abs(a.link() - b.link()) >= 2;
    }
    return switch (a.kind()) {
      case ROBOT -> robotVersus(a, b);
      case FIXTURE, PART -> switch (b.kind()) {
        case ROBOT -> robotVersus(b, a);
        case FIXTURE, PART -> isHeld(a) || isHeld(b);
      };
    };
  }

  private boolean robotVersus(Body robot, Body other) {
    return switch (other.kind()) {
      case ROBOT -> true;
      case FIXTURE -> robot.link() != 0;
      case PART -> !robot.owner().equals(holderByPart.get(other.owner()));
    };
  }

  private boolean isHeld(Body b) {
    return b.kind() == BodyKind.PART && holderByPart.containsKey(b.owner());
  }
}
