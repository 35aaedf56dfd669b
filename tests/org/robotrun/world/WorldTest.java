package org.robotrun.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;

class WorldTest {
  private static final WorldObject TABLE = WorldObject.of("table", ObjectKind.FIXTURE, new Shape.Box(400, 600, 200),
      Rgb.GREY, Transform.translation(500, 0, -300), Optional.empty());
  private static final WorldObject JIG = WorldObject.of("jig", ObjectKind.FIXTURE, new Shape.Box(100, 100, 10),
      Rgb.GREY, Xyzwpr.ofDegrees(0, 0, 200, 0, 0, 90).toTransform(), Optional.of("table"));
  private static final WorldObject PART = WorldObject.of("part", ObjectKind.PART, new Shape.Cylinder(20, 50),
      Rgb.GREY, Transform.translation(30, 0, 10), Optional.of("jig"));

  @Test
  void posesFollowTheParentChain() {
    World w = new World(List.of(TABLE, JIG, PART));
    // Method: composed by hand; the jig is turned 90 deg, so the part's local +x is cell +y.
    Transform X_CP = w.poseInCell("part");
    assertThat(X_CP.x()).isCloseTo(500, within(1e-9));
    assertThat(X_CP.y()).isCloseTo(30, within(1e-9));
    assertThat(X_CP.z()).isCloseTo(-90, within(1e-9));
    Obb box = w.collisionBox("part");
    assertThat(box.cz()).isCloseTo(-65, within(1e-9));
    assertThat(box.hx()).isEqualTo(20);
    assertThat(box.hz()).isEqualTo(25);
  }

  @Test
  void resetPutsMovedPartsBack() {
    World w = new World(List.of(TABLE, JIG, PART));
    WorldObject moved = w.find("part").orElseThrow().movedTo(Transform.translation(1, 2, 3), Optional.empty());
    World after = w.with(moved);
    assertThat(after.poseInCell("part")).isEqualTo(Transform.translation(1, 2, 3));
    World reset = after.reset();
    assertThat(reset).isEqualTo(w);
    assertThat(reset.find("part").orElseThrow().parent()).contains("jig");
  }

  @Test
  void namesParentsAndLoopsAreChecked() {
    assertThatThrownBy(() -> new World(List.of(TABLE, TABLE))).hasMessageContaining("two objects are named 'table'");
    assertThatThrownBy(() -> new World(List.of(PART))).hasMessageContaining("parent 'jig' does not exist");
    WorldObject onPart = WorldObject.of("x", ObjectKind.PART, new Shape.Box(1, 1, 1), Rgb.GREY, Transform.IDENTITY,
        Optional.of("part"));
    assertThatThrownBy(() -> new World(List.of(TABLE, JIG, PART, onPart))).hasMessageContaining("is not a fixture");
    WorldObject loopTable = WorldObject.of("table", ObjectKind.FIXTURE, new Shape.Box(1, 1, 1), Rgb.GREY,
        Transform.IDENTITY, Optional.of("jig"));
    assertThatThrownBy(() -> new World(List.of(loopTable, JIG))).hasMessageContaining("loop");
  }

  @Test
  void shapesStandOnTheirOrigin() {
    assertThat(new Shape.Box(10, 20, 30).boundingBox())
        .isEqualTo(new LocalBox(Transform.translation(0, 0, 15), 5, 10, 15));
    assertThatThrownBy(() -> new Shape.Box(10, -1, 30)).hasMessageContaining("width must be a finite number > 0");
    assertThatThrownBy(() -> new Shape.Cylinder(Double.NaN, 1)).hasMessageContaining("radius");
  }

  @Test
  void meshBoxIsItsBounds() {
    TriangleMesh tri = new TriangleMesh(new float[] {0, 0, 0, 10, 0, 0, 0, 20, 4});
    Shape.Mesh mesh = new Shape.Mesh(java.nio.file.Path.of("m.stl"), 1, tri);
    LocalBox b = mesh.boundingBox();
    assertThat(b.X_LB().translationVector()).isEqualTo(new Vec3(5, 10, 2));
    assertThat(b.hxMm()).isEqualTo(5);
    assertThat(b.hyMm()).isEqualTo(10);
    assertThat(b.hzMm()).isEqualTo(2);
  }

  @Test
  void linkBoxesFollowTheirLink() {
    // A cylinder along the link's x (turned about y), radius 40, length 220: its box in WORLD.
    LocalBox c = LocalBox.ofCylinder(Transform.rotation(0, 1, 0, Math.PI / 2).withTranslation(150, 0, 0), 40, 220);
    Obb box = c.inWorld(Transform.translation(0, 0, 100));
    assertThat(box.cx()).isEqualTo(150);
    assertThat(box.cz()).isEqualTo(100);
    assertThat(box.hz()).isEqualTo(110);
    // Local z (length) lies along WORLD x: the +x+y+z corner is 110 mm beyond the centre in x.
    assertThat(box.corner(7)[0]).isCloseTo(260, within(1e-9));
    assertThat(LocalBox.ofBox(Transform.IDENTITY, new Vec3(2, 4, 6)).hyMm()).isEqualTo(2);
  }

  @Test
  void worldObjectsBecomeCollisionBodiesThatFollowMoves() {
    World w = new World(List.of(TABLE, JIG, PART));
    org.robotrun.collision.CollisionWorld cw =
        new org.robotrun.collision.CollisionWorld(org.robotrun.collision.PairFilter.DIFFERENT_OWNERS);
    WorldBodies bodies = new WorldBodies(w, cw);
    // The part rests on the jig and the jig on the table (DIFFERENT_OWNERS checks every pair).
    assertThat(cw.box(bodies.handle("part"))).isEqualTo(w.collisionBox("part"));
    World moved = w.with(w.find("part").orElseThrow().movedTo(Transform.translation(0, 0, 5000), Optional.empty()));
    bodies.sync(moved, cw);
    assertThat(cw.box(bodies.handle("part")).cz()).isEqualTo(5025);
    cw.update();
    assertThat(cw.isTouching(bodies.handle("part"))).isFalse();
    assertThat(cw.isTouching(bodies.handle("jig"))).isTrue(); // the jig sits on the table
  }

  @Test
  void robotBoxesFollowTheirLinksAndSkipAdjacentOnes() {
    org.robotrun.collision.CollisionWorld cw = new org.robotrun.collision.CollisionWorld(
        org.robotrun.collision.StandardPairFilter.nothingHeld());
    // Three links folded onto each other: links 0 and 1 overlap (adjacent, ignored), 0 and 2 too (checked).
    LocalBox box = LocalBox.ofBox(Transform.translation(0, 0, 50), new Vec3(40, 40, 100));
    RobotBodies robot = new RobotBodies("r1", List.of(List.of(box), List.of(box), List.of(box, box)), cw);
    assertThat(robot.size()).isEqualTo(4);
    assertThat(cw.body(robot.handle(3)).name()).isEqualTo("r1/link2#2");
    Transform[] X_WL = {Transform.IDENTITY, Transform.translation(0, 0, 30), Transform.translation(0, 0, 1000)};
    robot.moveTo(X_WL, cw);
    assertThat(cw.box(robot.handle(1)).cz()).isEqualTo(80);
    assertThat(cw.update()).isZero();
    X_WL[2] = Transform.translation(0, 0, 90);
    robot.moveTo(X_WL, cw);
    assertThat(cw.update()).isEqualTo(2); // both boxes of link 2 against link 0
  }
}
