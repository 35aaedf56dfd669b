package org.robotrun.motion;

import java.util.Optional;
import org.robotrun.math.Vec3;

/** Circle helpers for callers that build circular moves from taught points (the A instruction). */
public final class ArcPoints {
  private ArcPoints() {}

  /**
   * On the circle through p0, p1 and p2 (in that order along the circle), the point halfway
   * along the arc from p1 to p2: a via point for a circular move that continues the arc p0 → p1
   * on to p2. Empty when the points are on one line or coincide.
   */
  public static Optional<Vec3> continuationVia(Vec3 p0, Vec3 p1, Vec3 p2) {
    PathShape.Arc arc = PathShape.Arc.through(p0, p1, p2);
    if (arc == null) {
      return Optional.empty();
    }
    Vec3 d1 = p1.minus(arc.center());
    double a1 = Math.atan2(d1.dot(arc.e2()), d1.dot(arc.e1()));
    if (a1 < 0) {
      a1 += 2 * Math.PI;
    }
    double mid = 0.5 * (a1 + arc.sweepRad());
    return Optional.of(arc.center().plus(arc.e1().times(arc.radius() * Math.cos(mid)))
        .plus(arc.e2().times(arc.radius() * Math.sin(mid))));
  }
}
