package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Vec3;

/**
 * The derivation's line geometry on lines no arm axis pair has (oblique, not unit length), and
 * its promise to round away the last bits of round-off: the library arms' derived parameters are
 * the published OPW numbers exactly (tests/resources/robots/chain-facts.json, ROS-I's
 * opw_parameters files), not 834.9999999999999 for 835, and the offsets published as 0 are 0.
 */
class OpwDerivationGeometryTest {

  @Test
  void twoObliqueLinesMeetAtTheirCommonPoint() {
    // Both lines through (10, -20, 30): directions at 40° to each other, neither of unit length.
    Vec3 x = new Vec3(10, -20, 30);
    Vec3 d = new Vec3(3, 0, 0);
    Vec3 e = new Vec3(Math.cos(Math.toRadians(40)) * 2, Math.sin(Math.toRadians(40)) * 2, 0);
    Vec3 p = x.minus(d.times(7));
    Vec3 q = x.plus(e.times(4));
    Vec3 m = OpwDerivation.intersection(p, d, q, e).orElseThrow();
    assertThat(m.distanceTo(x)).isLessThan(1e-9);
    // Parallel lines have no common point; lines that miss by more than the tolerance neither.
    assertThat(OpwDerivation.intersection(p, d, q, d.times(-2))).isEmpty();
    assertThat(OpwDerivation.intersection(p, d, q.plus(new Vec3(0, 0, 1e-3)), e)).isEmpty();
    assertThat(OpwDerivation.intersection(p, d, q.plus(new Vec3(0, 0, 1e-3)), e, 2e-3)).isPresent();
  }

  @Test
  void linesExactlyTheToleranceApartStillMeet() {
    // Closest points (0, 0, 0) and (0, 0, 1e-6): 1e-6 mm apart, the tolerance itself ("within").
    Vec3 o = new Vec3(0, 0, 0);
    Vec3 up = new Vec3(0, 0, 1e-6);
    assertThat(o.distanceTo(up)).isEqualTo(1e-6);
    Vec3 m = OpwDerivation.intersection(o, Vec3.X, up, Vec3.Y).orElseThrow();
    assertThat(m.z()).isCloseTo(0.5e-6, org.assertj.core.api.Assertions.within(1e-15));
    assertThat(OpwDerivation.intersection(o, Vec3.X, new Vec3(0, 0, 1.5e-6), Vec3.Y)).isEmpty();
  }

  @Test
  void theDistanceOfAPointFromALineWithALongDirection() {
    // The line through (1, 2, 3) along (0, 0, 5): the point (4, 6, -8) is 5 from it.
    assertThat(OpwDerivation.lineDistance(new Vec3(4, 6, -8), new Vec3(1, 2, 3), new Vec3(0, 0, 5)))
        .isCloseTo(5, org.assertj.core.api.Assertions.within(1e-12));
    assertThat(OpwDerivation.lineDistance(new Vec3(1, 2, 40), new Vec3(1, 2, 3), new Vec3(0, 0, 5))).isZero();
  }

  @ParameterizedTest
  @ValueSource(strings = {"lrmate200id", "lrmate200id4s", "er4ia", "m10ia", "m10id12", "m20ia", "r2000ic165f"})
  void theDerivedParametersAreThePublishedNumbersToTheLastBit(String id) throws Exception {
    JsonNode o;
    try (var in = OpwDerivationGeometryTest.class.getResourceAsStream("/robots/chain-facts.json")) {
      o = new com.fasterxml.jackson.databind.ObjectMapper().readTree(in).get("models").get(id).get("opw");
    }
    OpwParameters p = OpwDerivation.derive(RobotDefinitions.load(id)).orElseThrow();
    assertThat(new double[] {p.a1(), p.a2(), p.b(), p.c1(), p.c2(), p.c3(), p.c4()}).as(id).containsExactly(
        o.get("a1").asDouble(), o.get("a2").asDouble(), o.get("b").asDouble(), o.get("c1").asDouble(),
        o.get("c2").asDouble(), o.get("c3").asDouble(), o.get("c4").asDouble());
    for (int i = 0; i < 6; i++) {
      double deg = o.get("offsets_deg").get(i).asDouble();
      if (deg == 0) {
        assertThat(Math.abs(p.offsetRad(i))).as("%s offset %d", id, i + 1).isZero();
      }
    }
  }
}
