package org.robotrun.sim;

import org.robotrun.collision.Body;
import org.robotrun.collision.BodyKind;
import org.robotrun.collision.PairFilter;
import org.robotrun.collision.StandardPairFilter;

/**
 * The simulation's collision rules: {@link StandardPairFilter} for everything between different
 * owners, but within one robot only its tool against links 0..3 (base, shoulder, upper arm,
 * elbow). The link bodies are boxes around display shapes, and neighbouring links' boxes
 * overlap around every joint (the elbow housing and the forearm at HOME, for instance), so
 * link-against-link checks would alarm in ordinary poses; a tool driven into its own arm is the
 * self-collision a student can cause.
 */
record CellPairFilter(StandardPairFilter standard) implements PairFilter {

  @Override
  public boolean mayCollide(Body a, Body b) {
    if (a.owner().equals(b.owner()) && a.kind() == BodyKind.ROBOT && b.kind() == BodyKind.ROBOT) {
      return (a.link() == Body.TOOL_LINK && b.link() <= 3) || (b.link() == Body.TOOL_LINK && a.link() <= 3);
    }
    return standard.mayCollide(a, b);
  }
}
