package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.bench.ObbPairGenerator;
import org.robotrun.collision.bench.ObbPairGenerator.Expect;
import org.robotrun.collision.bench.ObbPairGenerator.Kind;
import org.robotrun.collision.bench.ObbPairGenerator.LabeledPair;
import org.robotrun.math.Transform;

class SeparatingAxisTestTest {
  private static final double TOL = SeparatingAxisTest.CONTACT_TOLERANCE_MM;

  @Test
  void agreesWithBruteForceOnHundredThousandSeededPairs() {
    // Method: SAT vs edge-against-solid clipping (both closed, touching within 1e-6 mm counts),
    // plus the construction's own answer for built contacts (gap ≤ 5e-7 mm → touching,
    // ≥ 3e-6 mm → apart). Tolerance: none — zero disagreements.
    List<LabeledPair> pairs = new ObbPairGenerator(20261122L).pairs(100_000);
    double[] flatA = new double[pairs.size() * Obb.STRIDE];
    double[] flatB = new double[pairs.size() * Obb.STRIDE];
    for (int i = 0; i < pairs.size(); i++) {
      pairs.get(i).a().writeTo(flatA, i);
      pairs.get(i).b().writeTo(flatB, i);
    }
    List<String> disagreements = new ArrayList<>();
    Map<Kind, int[]> tally = new EnumMap<>(Kind.class);
    for (int i = 0; i < pairs.size(); i++) {
      LabeledPair p = pairs.get(i);
      boolean sat = SeparatingAxisTest.overlap(flatA, i, flatB, i);
      boolean satSwapped = SeparatingAxisTest.overlap(p.b(), p.a());
      boolean ref = BruteForceOverlap.overlap(p.a(), p.b(), TOL);
      boolean expected = switch (p.expect()) {
        case OVERLAP -> true;
        case SEPARATE -> false;
        case UNKNOWN -> ref;
      };
      if (sat != ref || satSwapped != ref || ref != expected) {
        disagreements.add("#" + i + " " + p.kind() + " expect=" + p.expect() + " sat=" + sat
            + " swapped=" + satSwapped + " ref=" + ref + " " + p.a() + " " + p.b());
      }
      int[] t = tally.computeIfAbsent(p.kind(), k -> new int[2]);
      t[sat ? 0 : 1]++;
    }
    assertThat(disagreements).as("disagreements (first ones)").isEmpty();
    // The mix is meaningful: every kind occurs, and each has both outcomes.
    assertThat(tally).hasSize(Kind.values().length);
    tally.forEach((kind, t) -> {
      if (kind != Kind.NESTED) {
        assertThat(t[0]).as("%s overlapping", kind).isGreaterThan(1000);
        assertThat(t[1]).as("%s apart", kind).isGreaterThan(1000);
      }
    });
  }

  @Test
  void faceContactIsOverlapAndAHairApartIsNot() {
    // Method: axis-aligned unit cubes; gaps exact in binary. Tolerance 1e-6 mm as documented.
    Obb a = Obb.axisAligned(0, 0, 0, 1, 1, 1);
    assertThat(SeparatingAxisTest.overlap(a, Obb.axisAligned(2, 0, 0, 1, 1, 1))).isTrue();
    assertThat(SeparatingAxisTest.overlap(a, Obb.axisAligned(2 + 0.5e-6, 0, 0, 1, 1, 1))).isTrue();
    assertThat(SeparatingAxisTest.overlap(a, Obb.axisAligned(2 + 2e-6, 0, 0, 1, 1, 1))).isFalse();
  }

  @Test
  void edgeCrossingEdgeIsFoundOnlyByTheCrossAxis() {
    // Method: B turned 45° about z and 45° about x, its lowest edge just above A's top edge;
    // every face axis overlaps, only an edge×edge axis separates. Tolerance: exact construction.
    Transform X_WB = Transform.rotation(0, 0, 1, Math.PI / 4).compose(Transform.rotation(1, 0, 0, Math.PI / 4));
    double h = 1;
    // B's lowest point along z is an edge; A's top-front edge runs along x at (y=1, z=1).
    Obb probe = Obb.of(X_WB, h, h, h);
    double lowest = 0;
    for (int i = 0; i < 8; i++) {
      lowest = Math.min(lowest, probe.corner(i)[2]);
    }
    Obb a = Obb.axisAligned(0, 0, 0, 1, 1, 1);
    Obb touching = Obb.of(X_WB.withTranslation(0, 1, 1 - lowest), h, h, h);
    Obb apart = Obb.of(X_WB.withTranslation(0, 1, 1 - lowest + 0.01), h, h, h);
    assertThat(SeparatingAxisTest.overlap(a, touching)).isTrue();
    assertThat(SeparatingAxisTest.overlap(a, apart)).isFalse();
    assertThat(BruteForceOverlap.overlap(a, apart, TOL)).isFalse();
  }

  @Test
  void flatArrayFormGivesTheSameAnswer() {
    List<LabeledPair> pairs = new ObbPairGenerator(7).pairs(2000);
    double[] as = new double[pairs.size() * Obb.STRIDE];
    double[] bs = new double[pairs.size() * Obb.STRIDE];
    for (int i = 0; i < pairs.size(); i++) {
      pairs.get(i).a().writeTo(as, i);
      pairs.get(i).b().writeTo(bs, i);
    }
    for (int i = 0; i < pairs.size(); i++) {
      assertThat(SeparatingAxisTest.overlap(as, i, bs, i))
          .isEqualTo(SeparatingAxisTest.overlap(pairs.get(i).a(), pairs.get(i).b()));
      assertThat(Obb.readFrom(as, i)).isEqualTo(pairs.get(i).a());
    }
  }

  @Test
  void generatorLabelsAreHonouredByTheReference() {
    // Guards the test data itself: constructed gaps give the labelled outcome in the reference.
    for (LabeledPair p : new ObbPairGenerator(99).pairs(5000)) {
      if (p.expect() != Expect.UNKNOWN) {
        assertThat(BruteForceOverlap.overlap(p.a(), p.b(), TOL)).as("%s", p).isEqualTo(p.expect() == Expect.OVERLAP);
      }
    }
  }
}
