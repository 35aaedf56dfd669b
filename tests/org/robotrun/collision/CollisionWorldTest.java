package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

class CollisionWorldTest {

  @Test
  void broadPhaseFindsTheSamePairsAsAllPairsOnRandomScenes() {
    // Method: 2 robots × 8 boxes + 200 objects in a 2 m cell, moved over 50 ticks; the set of
    // touching pairs must equal the filtered O(n²) SAT result at every tick.
    Random random = new Random(6);
    int contactsSeen = 0;
    for (int scene = 0; scene < 10; scene++) {
      CollisionWorld world = new CollisionWorld(new StandardPairFilter(Map.of("part3", "robot1")));
      List<Obb> boxes = new ArrayList<>();
      for (int r = 1; r <= 2; r++) {
        for (int k = 0; k < 8; k++) {
          boxes.add(randomBox(random, 600, 40, 200));
          world.add(Body.robotLink("robot" + r, k, "robot" + r + "/box" + k), boxes.getLast());
        }
      }
      for (int o = 0; o < 200; o++) {
        boxes.add(randomBox(random, 1000, 5, 120));
        String name = (o % 3 == 0 ? "fixture" : "part") + o;
        Body body = o % 3 == 0 ? Body.fixture(name, name) : Body.part(name, name);
        world.add(body, boxes.getLast());
      }
      for (int tick = 0; tick < 50; tick++) {
        // Robots and a handful of objects move a little each tick.
        for (int h = 0; h < world.size(); h++) {
          if (h < 16 || random.nextInt(20) == 0) {
            Obb b = world.box(h);
            world.setBox(h, Obb.of(
                Transform.translation(random.nextGaussian() * 20, random.nextGaussian() * 20, random.nextGaussian() * 20)
                    .compose(b.pose()).compose(Transform.rotation(0, 0, 1, random.nextGaussian() * 0.1)),
                b.hx(), b.hy(), b.hz()));
          }
        }
        contactsSeen += world.update();
        assertThat(pairsOf(world)).isEqualTo(allPairs(world));
      }
    }
    assertThat(contactsSeen).as("the scenes have contacts to find").isGreaterThan(1000);
  }

  @Test
  void exclusionRulesOfTheStandardFilter() {
    StandardPairFilter nothing = StandardPairFilter.nothingHeld();
    Body l2 = Body.robotLink("r1", 2, "r1/link2");
    Body l3 = Body.robotLink("r1", 3, "r1/link3");
    Body l5 = Body.robotLink("r1", 5, "r1/link5");
    Body tool = Body.robotLink("r1", Body.TOOL_LINK, "r1/tool");
    Body base = Body.robotLink("r1", 0, "r1/base");
    Body other = Body.robotLink("r2", 3, "r2/link3");
    Body table = Body.fixture("table", "table");
    Body jig = Body.fixture("jig", "jig");
    Body part = Body.part("p1", "p1");
    assertThat(nothing.mayCollide(l2, l3)).as("adjacent links").isFalse();
    assertThat(nothing.mayCollide(l3, l5)).as("self-collision").isTrue();
    assertThat(nothing.mayCollide(tool, l5)).as("tool vs link 5").isTrue();
    assertThat(nothing.mayCollide(l2, other)).as("robot vs robot").isTrue();
    assertThat(nothing.mayCollide(base, table)).as("base on its stand").isFalse();
    assertThat(nothing.mayCollide(l2, table)).isTrue();
    assertThat(nothing.mayCollide(table, jig)).as("static vs static").isFalse();
    assertThat(nothing.mayCollide(part, table)).as("part at rest").isFalse();
    assertThat(nothing.mayCollide(tool, part)).as("robot vs free part").isTrue();
    StandardPairFilter held = new StandardPairFilter(Map.of("p1", "r1"));
    assertThat(held.mayCollide(tool, part)).as("held part vs its gripper").isFalse();
    assertThat(held.mayCollide(part, l3)).as("held part vs its robot").isFalse();
    assertThat(held.mayCollide(part, other)).as("held part vs the other robot").isTrue();
    assertThat(held.mayCollide(table, part)).as("held part vs fixture").isTrue();
  }

  @Test
  void contactsFoundAtAReferencePoseCanBeAllowed() {
    // Links 2 and 4 overlap by construction; links 2 and 5 only when the arm folds.
    CollisionWorld world = new CollisionWorld(StandardPairFilter.nothingHeld());
    int l2 = world.add(Body.robotLink("r1", 2, "r1/link2"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
    world.add(Body.robotLink("r1", 4, "r1/link4"), Obb.axisAligned(15, 0, 0, 10, 10, 10));
    int l5 = world.add(Body.robotLink("r1", 5, "r1/link5"), Obb.axisAligned(100, 0, 0, 10, 10, 10));
    world.add(Body.fixture("table", "table"), Obb.axisAligned(0, 0, -25, 100, 100, 5)); // 10 mm below
    world.update();
    java.util.Set<BodyPair> allowed = StandardPairFilter.robotSelfContacts(world.contacts());
    assertThat(allowed).containsExactly(new BodyPair("r1/link4", "r1/link2"));
    world.setFilter(StandardPairFilter.nothingHeld().withAllowedContacts(allowed));
    assertThat(world.update()).as("the structural contact is gone").isZero();
    world.setBox(l5, Obb.axisAligned(0, 0, 15, 10, 10, 10));
    assertThat(world.update()).as("link 5 folded onto link 2 (link 4 is its neighbour)").isEqualTo(1);
    assertThat(world.isTouching(l5)).isTrue();
    assertThat(world.isTouching(l2)).isTrue();
  }

  @Test
  void touchingQueryMarksBothBodiesAndOnlyThem() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    int a = world.add(Body.fixture("a", "a"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
    int b = world.add(Body.fixture("b", "b"), Obb.axisAligned(20, 0, 0, 10, 10, 10)); // face contact
    int c = world.add(Body.fixture("c", "c"), Obb.axisAligned(100, 0, 0, 10, 10, 10));
    assertThat(world.update()).isEqualTo(1);
    assertThat(world.isTouching(a)).isTrue();
    assertThat(world.isTouching(b)).isTrue();
    assertThat(world.isTouching(c)).isFalse();
    assertThat(world.contacts()).containsExactly(new Contact(world.body(a), world.body(b)));
    world.setPose(c, Transform.translation(0, 0, 15), Transform.translation(0, 0, 0));
    assertThat(world.update()).isEqualTo(3);
    assertThat(world.isTouching(c)).isTrue();
  }

  @Test
  void newFilterTakesEffectAtTheNextUpdate() {
    // A part held by the robot overlaps its gripper: no contact while held, a contact once released.
    CollisionWorld world = new CollisionWorld(new StandardPairFilter(Map.of("p1", "r1")));
    int tool = world.add(Body.robotLink("r1", Body.TOOL_LINK, "r1/tool"), Obb.axisAligned(0, 0, 0, 10, 10, 10));
    int part = world.add(Body.part("p1", "p1"), Obb.axisAligned(0, 0, -15, 10, 10, 10));
    assertThat(world.update()).isZero();
    world.setFilter(StandardPairFilter.nothingHeld());
    assertThat(world.update()).isEqualTo(1);
    assertThat(world.contacts()).containsExactly(new Contact(world.body(tool), world.body(part)));
  }

  @Test
  void probeQueryFindsTheOverlappingBodiesItAccepts() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    world.add(Body.fixture("table", "table"), Obb.axisAligned(0, 0, -10, 500, 500, 10));
    int near = world.add(Body.part("p1", "p1"), Obb.axisAligned(0, 0, 20, 20, 20, 20));
    world.add(Body.part("p2", "p2"), Obb.axisAligned(300, 0, 20, 20, 20, 20));
    // A pickup zone just above p1, touching its top face: p1 only, since the filter drops fixtures.
    Obb zone = Obb.axisAligned(0, 0, 45, 10, 10, 5);
    assertThat(world.overlapping(zone, b -> b.kind() == BodyKind.PART)).containsExactly(near);
    assertThat(world.overlapping(zone, b -> true)).containsExactly(near);
    assertThat(world.overlapping(Obb.axisAligned(0, 0, 0, 1, 1, 1), b -> true)).containsExactly(0, near);
  }

  @Test
  void setPoseComposesLinkAndLocalFrames() {
    CollisionWorld world = new CollisionWorld(PairFilter.DIFFERENT_OWNERS);
    int h = world.add(Body.part("p", "p"), Obb.axisAligned(0, 0, 0, 1, 2, 3));
    Transform X_WL = Transform.rotation(0, 0, 1, 0.7).withTranslation(5, 6, 7);
    Transform X_LB = Transform.rotation(1, 0, 0, 0.3).withTranslation(1, 2, 3);
    world.setPose(h, X_WL, X_LB);
    Transform expected = X_WL.compose(X_LB);
    Obb box = world.box(h);
    assertThat(box.pose().distanceTo(expected)).isLessThan(1e-12);
    assertThat(box.pose().rotationAngleTo(expected)).isLessThan(1e-12);
    assertThat(box.hz()).isEqualTo(3);
  }

  private static Set<Long> pairsOf(CollisionWorld world) {
    Set<Long> out = new HashSet<>();
    for (int k = 0; k < world.contactCount(); k++) {
      out.add(((long) world.contactA(k) << 32) | world.contactB(k));
    }
    assertThat(out).hasSize(world.contactCount()); // no pair twice
    return out;
  }

  private static Set<Long> allPairs(CollisionWorld world) {
    StandardPairFilter filter = new StandardPairFilter(Map.of("part3", "robot1"));
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

  private static Obb randomBox(Random random, double spread, double minHalf, double maxHalf) {
    Transform X_WB = Transform.rotation(0, 0, 1, random.nextDouble() * 6.3)
        .compose(Transform.rotation(1, 0, 0, random.nextDouble() * 6.3))
        .withTranslation(random.nextDouble() * 2 * spread - spread, random.nextDouble() * 2 * spread - spread,
            random.nextDouble() * spread);
    return Obb.of(X_WB, minHalf + random.nextDouble() * (maxHalf - minHalf),
        minHalf + random.nextDouble() * (maxHalf - minHalf), minHalf + random.nextDouble() * (maxHalf - minHalf));
  }
}
