package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;

class FrameTeachingTest {
  /** The tool to recover: TCP 20, −10, 180 mm from the flange, tilted. */
  private final Transform X_FT = Xyzwpr.ofDegrees(20, -10, 180, 15, -25, 40).toTransform();
  /** The fixed point the approaches touch (mm, world). */
  private final Vec3 p_WTouch = new Vec3(450, 120, 80);

  /** A flange pose with orientation (w, p, r deg) that puts the TCP on the touch point. */
  private Transform approach(double wDeg, double pDeg, double rDeg) {
    Transform R = Xyzwpr.ofDegrees(0, 0, 0, wDeg, pDeg, rDeg).toTransform();
    Vec3 tcpOffset = R.rotate(X_FT.translationVector());
    Vec3 t = p_WTouch.minus(tcpOffset);
    return R.withTranslation(t.x(), t.y(), t.z());
  }

  private List<Transform> goodApproaches() {
    return List.of(approach(180, 0, 0), approach(150, 30, 40), approach(-160, -25, -60));
  }

  @Test
  void threePointFindsTheTcp() {
    // Method: synthetic flange poses touching one point; TCP to 1e-6 mm, orientation = flange's.
    Transform taught = FrameTeaching.toolThreePoint(goodApproaches());
    assertThat(taught.translationVector().distanceTo(X_FT.translationVector())).isLessThan(1e-6);
    assertThat(taught.rotationAngleTo(Transform.IDENTITY)).isZero();
  }

  @Test
  void sixPointXzAndXyRecoverTheWholeToolFrame() {
    // Method: orient origin pose, then the TCP moved 100 mm along the tool's +X and +Z (or +Y)
    // with the same flange orientation; frame to 1e-6 mm and 1e-9 rad.
    Transform origin = approach(170, 10, 20);
    Transform R_WT = origin.compose(X_FT);
    for (FrameTeaching.SixPointVariant v : FrameTeaching.SixPointVariant.values()) {
      Vec3 second = v == FrameTeaching.SixPointVariant.XZ ? R_WT.axis(2) : R_WT.axis(1);
      // Skew the second direction toward X: the method must orthogonalise it.
      Vec3 skewed = second.times(80).plus(R_WT.axis(0).times(30));
      Transform taught = FrameTeaching.toolSixPoint(goodApproaches(), origin,
          moved(origin, R_WT.axis(0).times(100)), moved(origin, skewed), v);
      assertThat(taught.distanceTo(X_FT)).as("%s", v).isLessThan(1e-6);
      assertThat(taught.rotationAngleTo(X_FT)).as("%s", v).isLessThan(1e-9);
    }
  }

  @Test
  void userThreeAndFourPointRecoverTheFrame() {
    // Method: points made from a known user frame; frame to 1e-6 mm and 1e-9 rad.
    Transform X_WU = Xyzwpr.ofDegrees(600, -200, 150, 5, -10, 35).toTransform();
    Vec3 o = X_WU.apply(Vec3.ZERO);
    Vec3 x = X_WU.apply(new Vec3(250, 0, 0));
    Vec3 y = X_WU.apply(new Vec3(40, 180, 0));
    Transform three = FrameTeaching.userThreePoint(o, x, y);
    assertThat(three.distanceTo(X_WU)).isLessThan(1e-6);
    assertThat(three.rotationAngleTo(X_WU)).isLessThan(1e-9);

    // Four-point: orientation from points away from the origin, origin taught separately.
    Vec3 oo = X_WU.apply(new Vec3(100, 50, 0));
    Vec3 x4 = X_WU.apply(new Vec3(300, 50, 0));
    Vec3 y4 = X_WU.apply(new Vec3(90, 250, 0));
    Transform four = FrameTeaching.userFourPoint(oo, x4, y4, o);
    assertThat(four.distanceTo(X_WU)).isLessThan(1e-6);
    assertThat(four.rotationAngleTo(X_WU)).isLessThan(1e-9);
  }

  @Test
  void directEntryIsTheXyzwprPose() {
    Xyzwpr typed = Xyzwpr.ofDegrees(10, 20, 30, 0, 90, 0);
    assertThat(FrameTeaching.directEntry(typed)).isEqualTo(typed.toTransform());
  }

  @Test
  void coincidentUserPointsNameThePointToReteach() {
    Vec3 o = new Vec3(100, 100, 0);
    assertThatThrownBy(() -> FrameTeaching.userThreePoint(o, o.plus(new Vec3(0.3, 0, 0)), new Vec3(100, 300, 0)))
        .isInstanceOfSatisfying(FrameTeachingException.class, e -> {
          assertThat(e.point()).isEqualTo("X direction point");
          assertThat(e.getMessage()).startsWith("re-teach the X direction point: it is 0.30 mm from the origin point");
        });
    assertThatThrownBy(() -> FrameTeaching.userFourPoint(o, new Vec3(300, 100, 0), o, new Vec3(0, 0, 0)))
        .isInstanceOfSatisfying(FrameTeachingException.class,
            e -> assertThat(e.point()).isEqualTo("Y direction point"));
  }

  @Test
  void collinearUserPointsAskForTheYPointAgain() {
    assertThatThrownBy(() -> FrameTeaching.userThreePoint(
            new Vec3(0, 0, 0), new Vec3(200, 0, 0), new Vec3(-150, 2, 0)))
        .isInstanceOfSatisfying(FrameTeachingException.class, e -> {
          assertThat(e.point()).isEqualTo("Y direction point");
          assertThat(e.getMessage()).contains("from the line through the origin point and the X direction point");
        });
  }

  @Test
  void approachesWithTooSimilarOrientationsAreRejected() {
    List<Transform> similar = List.of(approach(180, 0, 0), approach(150, 30, 40), approach(152, 28, 45));
    assertThatThrownBy(() -> FrameTeaching.toolThreePoint(similar))
        .isInstanceOfSatisfying(FrameTeachingException.class, e -> {
          assertThat(e.point()).isEqualTo("approach point 3");
          assertThat(e.getMessage()).contains("from approach point 2");
        });
  }

  @Test
  void approachesTurningAboutOneAxisAreRejected() {
    // All three differ only by a turn about the flange z axis: the TCP's z is undetermined.
    Transform base = approach(180, 0, 0);
    List<Transform> aboutZ = List.of(base, turnedAboutFlangeZ(base, 60), turnedAboutFlangeZ(base, 140));
    assertThatThrownBy(() -> FrameTeaching.toolThreePoint(aboutZ))
        .isInstanceOfSatisfying(FrameTeachingException.class,
            e -> assertThat(e.getMessage()).contains("all turn about one axis"));
  }

  @Test
  void anApproachThatMissesThePointIsNamed() {
    Transform off = moved(approach(-160, -25, -60), new Vec3(0, 0, 15));
    List<Transform> approaches = List.of(approach(180, 0, 0), approach(150, 30, 40), off);
    assertThatThrownBy(() -> FrameTeaching.toolThreePoint(approaches))
        .isInstanceOfSatisfying(FrameTeachingException.class,
            e -> assertThat(e.point()).isEqualTo("approach point 3"));
  }

  @Test
  void sixPointWithTheZPointOnTheXLineIsRejected() {
    Transform origin = approach(170, 10, 20);
    Vec3 x = origin.compose(X_FT).axis(0);
    assertThatThrownBy(() -> FrameTeaching.toolSixPoint(goodApproaches(), origin,
            moved(origin, x.times(100)), moved(origin, x.times(-50)), FrameTeaching.SixPointVariant.XZ))
        .isInstanceOfSatisfying(FrameTeachingException.class,
            e -> assertThat(e.point()).isEqualTo("Z direction point"));
  }

  private static Transform moved(Transform X, Vec3 d) {
    return X.withTranslation(X.x() + d.x(), X.y() + d.y(), X.z() + d.z());
  }

  private static Transform turnedAboutFlangeZ(Transform X, double deg) {
    return X.compose(Transform.rotation(0, 0, 1, Math.toRadians(deg)));
  }
}
