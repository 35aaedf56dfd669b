package org.robotrun.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;

/**
 * Seeded random part placement ({@link VisionSetup.Placement}): the same seed gives the same
 * parts at the same places, on every machine ({@link Random}'s sequence is specified by its
 * documentation).
 */
public final class PartPlacement {
  /** Draws per part before the gap is given up for that part (the area is too small for the gap). */
  static final int TRIES = 2000;

  private PartPlacement() {}

  /**
   * {@code world} with every part of every placement group moved to a random place: x, y and the
   * rotation about z drawn, z, w and p kept; the new pose is also the part's start pose (Reset scene
   * puts it back there). A world with no placements comes back unchanged.
   */
  public static World place(World world, VisionSetup vision) {
    if (vision.placements().isEmpty()) {
      return world;
    }
    Random rnd = new Random(mix(vision.seed(), 0x9E3779B97F4A7C15L));
    World out = world;
    for (VisionSetup.Placement g : vision.placements()) {
      List<double[]> placed = new ArrayList<>();
      for (String name : g.parts()) {
        WorldObject o = out.find(name).orElseThrow(() -> new IllegalArgumentException("no part named '" + name + "'"));
        double x = 0;
        double y = 0;
        for (int t = 0; t < TRIES; t++) {
          x = uniform(rnd, g.xMinMm(), g.xMaxMm());
          y = uniform(rnd, g.yMinMm(), g.yMaxMm());
          if (clear(placed, x, y, g.minGapMm())) {
            break;
          }
        }
        double r = uniform(rnd, g.rMinRad(), g.rMaxRad());
        placed.add(new double[] {x, y});
        Xyzwpr was = Xyzwpr.fromTransform(o.startPose());
        Transform pose = Xyzwpr.of(x, y, was.z(), was.w(), was.p(), r).toTransform();
        Shape shape = o.shape();
        Rgb colour = o.colour();
        if (!g.kinds().isEmpty()) {
          VisionSetup.Kind k = g.kinds().get(rnd.nextInt(g.kinds().size()));
          shape = k.shape();
          colour = k.colour();
        }
        // A part that is not at its start (a saved cell reopened mid-run) stays where it is; only
        // its start is the placement's, so Reset scene puts it there (issue 26).
        boolean atStart = o.pose().equals(o.startPose()) && o.parent().equals(o.startParent());
        out = out.with(new WorldObject(o.name(), o.kind(), shape, colour, atStart ? pose : o.pose(),
            atStart ? o.startParent() : o.parent(), pose, o.startParent(), o.touchable()));
      }
    }
    return out;
  }

  private static boolean clear(List<double[]> placed, double x, double y, double gap) {
    for (double[] p : placed) {
      if (Math.hypot(p[0] - x, p[1] - y) < gap) {
        return false;
      }
    }
    return true;
  }

  private static double uniform(Random rnd, double lo, double hi) {
    return lo == hi ? lo : lo + (hi - lo) * rnd.nextDouble();
  }

  /** A 64-bit mix (SplitMix64's finaliser) so nearby seeds give unrelated sequences. */
  public static long mix(long a, long b) {
    long z = a * 0xBF58476D1CE4E5B9L + b;
    z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
    z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
    return z ^ (z >>> 31);
  }
}
