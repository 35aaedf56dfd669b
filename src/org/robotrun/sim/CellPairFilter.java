package org.robotrun.sim;

import org.robotrun.collision.Body;
import org.robotrun.collision.BodyKind;
import org.robotrun.collision.PairFilter;
import org.robotrun.collision.StandardPairFilter;

/**
 * The simulation's collision rules: {@link StandardPairFilter} for everything between different
 * owners (held parts, allowed contacts), and within one robot the links at least
 * {@link #SELF_LINK_GAP} apart (the end effector counts as link 7).
 *
 * <p>Why three and not two: link boxes are boxes around display shapes, coarser than the
 * castings, and two links joined through one link between them pivot about joints whose limits
 * keep them apart on the real arm. Sampling 20 000 random poses within the LR Mate's limits
 * (seed 1), the pairs two apart that touch are link 2's elbow housing against link 4's forearm
 * (in every pose), link 2's upper arm against link 4 once the elbow closes past about 70°, and
 * the base's column against the upper arm with J2 beyond about 120°: none of them a collision a
 * real LR Mate can have. Every pair three or more apart that touched in the sample is a real
 * fold (the wrist or tool driven into the base, the shoulder or the upper arm), and stays
 * checked. {@code CellPairFilterTest} repeats the sample.
 *
 * <p>Objects the scenario marks {@code touchable} (markers, pins: what a frame is taught on) are
 * not checked against any robot's end effector (link 7), so touching them is no alarm; the other
 * links still collide with them.
 */
record CellPairFilter(StandardPairFilter standard, java.util.Set<String> touchable) implements PairFilter {
  /** Links of one robot are checked against each other when at least this far apart. */
  static final int SELF_LINK_GAP = 3;

  CellPairFilter {
    touchable = java.util.Set.copyOf(touchable);
  }

  /** The rules with no touchable object. */
  CellPairFilter(StandardPairFilter standard) {
    this(standard, java.util.Set.of());
  }

  @Override
  public boolean mayCollide(Body a, Body b) {
    if (!touchable.isEmpty() && (toolOnTouchable(a, b) || toolOnTouchable(b, a))) {
      return false;
    }
    if (a.owner().equals(b.owner()) && a.kind() == BodyKind.ROBOT && b.kind() == BodyKind.ROBOT) {
      return Math.abs(a.link() - b.link()) >= SELF_LINK_GAP
          && !standard.allowedContacts().contains(org.robotrun.collision.BodyPair.of(a, b));
    }
    return standard.mayCollide(a, b);
  }

  /** {@code tool} is a robot's end effector (link 7) and {@code o} an object the scenario marks touchable. */
  private boolean toolOnTouchable(Body tool, Body o) {
    return tool.kind() == BodyKind.ROBOT && tool.link() == Body.TOOL_LINK && o.kind() != BodyKind.ROBOT
        && touchable.contains(o.owner());
  }
}
