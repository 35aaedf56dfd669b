package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Rgb;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/** Where a released part comes to rest: on level and tilted fixture faces, or nowhere. */
class SetDownTest {
  /** A 200 × 160 × 12 mm plate whose frame is {@code X_CJ} (bottom centre, z along its thickness). */
  static WorldObject jig(Transform X_CJ) {
    return WorldObject.of("jig", ObjectKind.FIXTURE, new Shape.Box(200, 160, 12), Rgb.GREY, X_CJ, Optional.empty());
  }

  static WorldObject part() {
    return WorldObject.of("part", ObjectKind.PART, new Shape.Box(40, 30, 20), Rgb.GREY, Transform.translation(0, 0, 500), Optional.empty());
  }

  /** The jig's top face centre raised by {@code h} mm along the jig's own z, with the jig's orientation. */
  static Transform onTop(Transform X_CJ, double h) {
    return X_CJ.compose(Transform.translation(10, -20, 12 + h));
  }

  /** Height of the part's bottom face above the jig's top face, along the jig's z (mm). */
  static double heightAboveTop(World w, Transform X_CJ) {
    Transform X_JP = X_CJ.inverse().compose(w.poseInCell("part"));
    return X_JP.z() - 12;
  }

  static World world(Transform X_CJ) {
    return new World(List.of(jig(X_CJ), part()));
  }

  @Test
  void partJustAboveATiltedJigIsSetOnItsFaceAlongTheFaceNormal() {
    // Tilted 15° about x, then turned 20° about z, as the frame-teaching scenario's jig.
    Transform X_CJ = Transform.translation(300, 50, 100)
        .compose(Transform.rotation(0, 0, 1, Math.toRadians(20)))
        .compose(Transform.rotation(1, 0, 0, Math.toRadians(15)));
    World w = world(X_CJ);
    Transform released = onTop(X_CJ, 1.5);
    WorldObject set = CellState.setDown(w, "part", released);
    World after = w.with(set);
    assertThat(set.parent()).contains("jig");
    assertThat(heightAboveTop(after, X_CJ)).isCloseTo(0, offset(1e-9));
    // Moved only along the face normal: same place on the face, same orientation.
    Transform X_JP = X_CJ.inverse().compose(after.poseInCell("part"));
    assertThat(X_JP.x()).isCloseTo(10, offset(1e-9));
    assertThat(X_JP.y()).isCloseTo(-20, offset(1e-9));
    assertThat(after.poseInCell("part").rotationAngleTo(released)).isLessThan(1e-12);
    // And it touches the jig without poking into it.
    Obb jigBox = after.collisionBox("jig");
    assertThat(jigBox.overlaps(after.collisionBox("part"))).isTrue();
  }

  @Test
  void partSunkSlightlyIntoATiltedJigIsLiftedOntoTheFace() {
    Transform X_CJ = Transform.translation(0, 0, 0).compose(Transform.rotation(0, 1, 0, Math.toRadians(-30)));
    World w = world(X_CJ);
    World after = w.with(CellState.setDown(w, "part", onTop(X_CJ, -1.0)));
    assertThat(after.find("part").orElseThrow().parent()).contains("jig");
    assertThat(heightAboveTop(after, X_CJ)).isCloseTo(0, offset(1e-9));
  }

  @Test
  void partFurtherThanTheSnapDistanceStaysWhereReleased() {
    Transform X_CJ = Transform.rotation(1, 0, 0, Math.toRadians(15));
    World w = world(X_CJ);
    Transform released = onTop(X_CJ, CellState.SNAP_MM + 1);
    WorldObject set = CellState.setDown(w, "part", released);
    assertThat(set.parent()).isEmpty();
    assertThat(set.pose().x()).isEqualTo(released.x());
    assertThat(set.pose().z()).isEqualTo(released.z());
  }

  @Test
  void aFaceSteeperThanTheLimitHoldsNothing() {
    Transform X_CJ = Transform.rotation(1, 0, 0, Math.toRadians(CellState.MAX_SUPPORT_TILT_DEG + 10));
    World w = world(X_CJ);
    Transform released = onTop(X_CJ, 1.0);
    WorldObject set = CellState.setDown(w, "part", released);
    assertThat(set.parent()).isEmpty();
    assertThat(set.pose().z()).isEqualTo(released.z());
  }

  @Test
  void partBesideTheJigAtTheRightHeightIsNotSetOnIt() {
    Transform X_CJ = Transform.IDENTITY;
    World w = world(X_CJ);
    // At the top's height but 300 mm off to the side: no footprint overlap.
    WorldObject set = CellState.setDown(w, "part", Transform.translation(300, 0, 13));
    assertThat(set.parent()).isEmpty();
  }

  @Test
  void levelJigStillActsAsBefore() {
    World w = world(Transform.translation(0, 0, 100));
    World after = w.with(CellState.setDown(w, "part", Transform.translation(10, 10, 113.5)));
    assertThat(after.find("part").orElseThrow().parent()).contains("jig");
    assertThat(after.poseInCell("part").z()).isCloseTo(112, offset(1e-9));
  }
}
