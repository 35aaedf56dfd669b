package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Frame teaching at its stated edges: a direction point must be "at least 1.0 mm" from the origin
 * point ({@link FrameTeaching#MIN_DISTANCE_MM}), so exactly 1.0 mm is taught (X, then Y) and a hair
 * less is refused naming that point; with fewer than three approach points the refusal names
 * the next approach point to record.
 */
class FrameTeachingBoundsTest {

  @Test
  void directionPointsExactlyTheMinimumDistanceAwayAreTaught() {
    Vec3 o = new Vec3(100, 200, 300);
    Vec3 x = new Vec3(101, 200, 300);
    Vec3 y = new Vec3(100, 201, 300);
    assertThat(x.minus(o).norm()).isEqualTo(FrameTeaching.MIN_DISTANCE_MM);
    assertThat(y.minus(o).norm()).isEqualTo(FrameTeaching.MIN_DISTANCE_MM);
    Transform f = FrameTeaching.userThreePoint(o, x, y);
    assertThat(f.distanceTo(Transform.translation(100, 200, 300))).isZero();
    assertThat(f.rotationAngleTo(Transform.IDENTITY)).isZero();
    Transform g = FrameTeaching.userFourPoint(o, x, y, new Vec3(5, 6, 7));
    assertThat(g.distanceTo(Transform.translation(5, 6, 7))).isZero();
    Vec3 xShort = new Vec3(100.999, 200, 300);
    assertThatThrownBy(() -> FrameTeaching.userThreePoint(o, xShort, y))
        .isInstanceOfSatisfying(FrameTeachingException.class, e -> assertThat(e.point()).isEqualTo("X direction point"))
        .hasMessage("re-teach the X direction point: it is 1.00 mm from the origin point (at least 1.0 mm needed)");
    Vec3 yShort = new Vec3(100, 200.999, 300);
    assertThatThrownBy(() -> FrameTeaching.userThreePoint(o, x, yShort))
        .isInstanceOfSatisfying(FrameTeachingException.class, e -> assertThat(e.point()).isEqualTo("Y direction point"));
  }

  @Test
  void twoApproachPointsAskForTheThird() {
    Transform a = Transform.translation(0, 0, 500);
    Transform b = a.compose(Transform.rotation(1, 0, 0, 0.5));
    assertThatThrownBy(() -> FrameTeaching.toolThreePoint(List.of(a, b)))
        .isInstanceOfSatisfying(FrameTeachingException.class, e -> assertThat(e.point()).isEqualTo("approach point 3"))
        .hasMessageContaining("three approach points are needed, 2 recorded");
  }
}
