package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * The broad phase's edge cases against the all-pairs answer (issue 31): a whole scene turned
 * round between updates (the sort repair gives up and sorts afresh), long boxes tilted about each
 * world axis (their world bounds reach far from the centre), contacts just inside and outside
 * the tolerance, equal starting x, hundreds of touching pairs, the filter's cache and its reset.
 */
class CollisionWorldEdgeTest {

  // Method: 120 boxes on a line along x with neighbours overlapping; each update mirrors every x
  // (the order along x reverses: far more shifts than the repair's budget) or shuffles them;
  // the touching pairs equal the all-pairs SAT answer after every update.
  @Test
  void aSceneTurnedRoundBetweenUpdatesIsStillSweptRight() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    int n = 120;
    List<Double> xs = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      xs.add(i * 15.0);
      world.add(Body.part("p" + i, "p" + i), Obb.axisAligned(i * 15.0, 0, (i % 3) * 5.0, 10, 10, 10));
    }
    Random rnd = new Random(8);
    for (int step = 0; step < 6; step++) {
      for (int i = 0; i < n; i++) {
        double x = step % 2 == 1 ? -xs.get(i) : xs.get(i);
        if (step >= 4) {
          x = rnd.nextInt(n) * 15.0;
        }
        Obb b = world.box(i);
        world.setBox(i, Obb.axisAligned(x, 0, b.pose().z(), 10, 10, 10));
      }
      world.update();
      assertThat(pairsOf(world)).as("step %d", step).isEqualTo(allPairs(world, PairFilter.DIFFERENT_OWNERS));
      assertThat(world.contactCount()).isPositive();
    }
  }

  // Method: a 1000 x 10 x 10 mm bar tilted 60° about each world axis in turn, and a small cube
  // placed just beyond the bar's far end, then pulled 1 mm into it: touching only when the
  // bar's own end reaches it, whatever axis the tilt is about (its world bounds must cover it).
  @Test
  void tiltedLongBarsReachWhatTheirEndsTouch() {
    double[][] axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (double[] a : axes) {
      // The bar's long axis is the tilted frame's x for tilts about y and z, y for a tilt about x.
      boolean aboutX = a[0] == 1;
      Transform tilt = Transform.rotation(a[0], a[1], a[2], Math.toRadians(60));
      Obb bar = aboutX ? Obb.of(tilt, 10, 500, 10) : Obb.of(tilt, 500, 10, 10);
      org.robotrun.math.Vec3 end = tilt.rotate(aboutX ? new org.robotrun.math.Vec3(0, 500, 0) : new org.robotrun.math.Vec3(500, 0, 0));
      for (double inside : new double[] {-1, 2}) {
        // The cube (half size 5 mm) overlaps the end face by `inside` mm (-1: a 1 mm gap).
        org.robotrun.math.Vec3 dir = end.normalized();
        org.robotrun.math.Vec3 c = end.plus(dir.times(5 - inside));
        CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
        world.add(Body.fixture("bar", "bar"), bar);
        world.add(Body.part("cube", "cube"), Obb.of(tilt.withTranslation(c.x(), c.y(), c.z()), 5, 5, 5));
        world.update();
        assertThat(world.contactCount()).as("tilt about %s, %s mm in", java.util.Arrays.toString(a), inside)
            .isEqualTo(inside > 0 ? 1 : 0);
      }
    }
  }

  // Method: two cubes face to face along each world axis, gaps of 2e-6 mm (beyond the contact
  // tolerance, 1e-6 mm: apart), 5e-7 mm (within it: touching, so the broad phase's bounds must
  // keep the pair), 0 (touching) and -0.1 mm; a third cube sharing the first's starting x.
  @Test
  void contactsAtTheToleranceAndEqualStartingX() {
    for (int axis = 0; axis < 3; axis++) {
      for (double gap : new double[] {2e-6, 5e-7, 0, -0.1}) {
        CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
        double[] c = {0, 0, 0};
        c[axis] = 20 + gap;
        world.add(Body.part("a", "a"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
        world.add(Body.part("b", "b"), Obb.axisAligned(c[0], c[1], c[2], 10, 10, 10));
        world.update();
        assertThat(world.contactCount()).as("axis %d gap %s", axis, gap).isEqualTo(gap > 1e-6 ? 0 : 1);
      }
    }
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    world.add(Body.part("a", "a"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
    world.add(Body.part("b", "b"), Obb.axisAligned(0, 0, 100, 10, 10, 10));
    world.add(Body.part("c", "c"), Obb.axisAligned(0, 0, 15, 10, 10, 10));
    world.update();
    assertThat(world.contacts()).extracting(x -> x.a().name() + "-" + x.b().name()).containsExactly("a-c");
  }

  // Method: 60 unit cubes all at one spot (1770 touching pairs, beyond every buffer's first
  // size): every pair is reported once, smaller handle first, in handle order, and each body
  // is marked touching; a lone body far away is not.
  @Test
  void hundredsOfContactsAreAllReportedInOrder() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    int n = 60;
    for (int i = 0; i < n; i++) {
      // Later handles further left: the sweep meets them in the reverse order of their handles.
      world.add(Body.part("p" + i, "p" + i), Obb.axisAligned(-i * 0.01, 0, 0, 1, 1, 1));
    }
    int far = world.add(Body.part("far", "far"), Obb.axisAligned(0, 0, 500, 1, 1, 1));
    assertThat(world.update()).isEqualTo(n * (n - 1) / 2);
    List<Contact> contacts = world.contacts();
    assertThat(contacts).hasSize(n * (n - 1) / 2);
    int k = 0;
    for (int i = 0; i < n; i++) {
      for (int j = i + 1; j < n; j++) {
        assertThat(contacts.get(k).a().name()).isEqualTo("p" + i);
        assertThat(contacts.get(k).b().name()).isEqualTo("p" + j);
        k++;
      }
      assertThat(world.isTouching(i)).isTrue();
    }
    assertThat(world.isTouching(far)).isFalse();
    for (int c = 0; c < world.contactCount(); c++) {
      assertThat(world.contactA(c)).isLessThan(world.contactB(c));
    }
  }

  // Method: a counting filter over 40 bodies that all touch: the first update asks it once per
  // pair (780), later updates not at all (the answers are kept); a new filter is asked again and
  // its answers rule from the next update (here: only pairs of even handles).
  @Test
  void theFilterIsAskedOncePerPairUntilItIsReplaced() {
    AtomicInteger asked = new AtomicInteger();
    CollisionWorld world = new CollisionWorld((a, b) -> {
      asked.incrementAndGet();
      return true;
    });
    int n = 40;
    for (int i = 0; i < n; i++) {
      world.add(Body.part("p" + i, "p" + i), Obb.axisAligned(0, i * 0.1, 0, 5, 5, 5));
    }
    assertThat(world.update()).isEqualTo(780);
    assertThat(asked.get()).isEqualTo(780);
    world.update();
    world.update();
    assertThat(asked.get()).isEqualTo(780);
    // At most half full (open addressing), and linear in the pairs: 9 bytes a slot (key + answer).
    assertThat(world.cacheBytes()).isGreaterThanOrEqualTo(2L * 780 * 9).isLessThanOrEqualTo(8L * 780 * 9 + 9 * 1024);
    AtomicInteger asked2 = new AtomicInteger();
    world.setFilter((a, b) -> {
      asked2.incrementAndGet();
      return Integer.parseInt(a.name().substring(1)) % 2 == 0 && Integer.parseInt(b.name().substring(1)) % 2 == 0;
    });
    assertThat(world.update()).isEqualTo(20 * 19 / 2);
    assertThat(asked2.get()).isEqualTo(780);
    assertThat(world.update()).isEqualTo(190);
    assertThat(asked2.get()).isEqualTo(780);
    assertThat(world.isTouching(1)).isFalse();
    assertThat(world.isTouching(2)).isTrue();
  }

  // Method: the probe query at a body's current pose (no update), with and without the accept
  // test; unknown handles are refused with the handle in the message.
  @Test
  void probeQueryAndUnknownHandles() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    int a = world.add(Body.part("a", "a"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
    int f = world.add(Body.fixture("f", "f"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
    world.setBox(a, Obb.axisAligned(300, 0, 0, 10, 10, 10));
    assertThat(world.overlapping(Obb.axisAligned(300, 0, 15, 5, 5, 5), b -> true)).containsExactly(a);
    assertThat(world.overlapping(Obb.axisAligned(0, 0, 0, 1, 1, 1), b -> true)).containsExactly(f);
    assertThat(world.overlapping(Obb.axisAligned(0, 0, 0, 1, 1, 1), b -> b.kind() == BodyKind.PART)).isEmpty();
    assertThat(world.overlapping(Obb.axisAligned(300, 0, 21, 5, 5, 5), b -> true)).isEmpty();
    assertThat(world.size()).isEqualTo(2);
    assertThat(world.body(f).name()).isEqualTo("f");
    for (int bad : new int[] {-1, 2}) {
      assertThatThrownBy(() -> world.box(bad)).isInstanceOf(IndexOutOfBoundsException.class).hasMessageContaining(String.valueOf(bad));
      assertThatThrownBy(() -> world.isTouching(bad)).isInstanceOf(IndexOutOfBoundsException.class);
      assertThatThrownBy(() -> world.setBox(bad, Obb.axisAligned(0, 0, 0, 1, 1, 1))).isInstanceOf(IndexOutOfBoundsException.class);
      assertThatThrownBy(() -> world.setPose(bad, Transform.IDENTITY, Transform.IDENTITY)).isInstanceOf(IndexOutOfBoundsException.class);
    }
  }

  // Method: setPose(X_WL, X_LB) against X_WL·X_LB composed by Transform, for seeded general
  // poses (every rotation element and translation non-zero); the half sizes stay.
  @Test
  void setPoseIsTheComposedTransformForGeneralPoses() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    int h = world.add(Body.part("p", "p"), Obb.axisAligned(0, 0, 0, 3, 4, 5));
    Random rnd = new Random(12);
    for (int k = 0; k < 20; k++) {
      Transform X_WL = Transform.fromRpy(rnd.nextDouble() * 900 - 450, rnd.nextDouble() * 900 - 450, rnd.nextDouble() * 900,
          rnd.nextDouble() * 6 - 3, rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 6 - 3);
      Transform X_LB = Transform.fromRpy(rnd.nextDouble() * 200 - 100, rnd.nextDouble() * 200 - 100, rnd.nextDouble() * 200 - 100,
          rnd.nextDouble() * 6 - 3, rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 6 - 3);
      world.setPose(h, X_WL, X_LB);
      Transform expected = X_WL.compose(X_LB);
      Obb box = world.box(h);
      assertThat(box.pose().distanceTo(expected)).isLessThan(1e-9);
      double[] a = box.pose().rotationRowMajor(), b = expected.rotationRowMajor();
      for (int i = 0; i < 9; i++) {
        assertThat(a[i]).isCloseTo(b[i], org.assertj.core.api.Assertions.within(1e-12));
      }
      assertThat(new double[] {box.hx(), box.hy(), box.hz()}).containsExactly(3, 4, 5);
    }
  }

  private static Set<Long> pairsOf(CollisionWorld world) {
    Set<Long> out = new HashSet<>();
    for (int k = 0; k < world.contactCount(); k++) {
      out.add(((long) world.contactA(k) << 32) | world.contactB(k));
    }
    assertThat(out).hasSize(world.contactCount());
    return out;
  }

  private static Set<Long> allPairs(CollisionWorld world, PairFilter filter) {
    Set<Long> out = new HashSet<>();
    for (int i = 0; i < world.size(); i++) {
      for (int j = i + 1; j < world.size(); j++) {
        if (filter.mayCollide(world.body(i), world.body(j)) && world.box(i).overlaps(world.box(j))) {
          out.add(((long) i << 32) | j);
        }
      }
    }
    return out;
  }
}
