import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import org.robotrun.collision.SeparatingAxisTest;

/**
 * EXPERIMENT, not part of the build: the 15-axis OBB test of
 * {@link SeparatingAxisTest#overlap(double[], int, double[], int)}, four pairs at a time with
 * the incubating Vector API (256-bit lanes), branch-free. Every pair gets all 15 axes; the
 * operations are the scalar test's, in the same order and without fused multiply-add, so the
 * answers are bit for bit the scalar ones.
 *
 * <p>Input layout: blocks of 4 pairs; in each block the 30 fields (box A: cx, cy, cz, hx, hy,
 * hz, r11..r33; then box B the same) each hold 4 lanes: {@code D[(block*30 + field)*4 + lane]}.
 * One array keeps one stream for the hardware prefetcher. Why the kernel is one method with
 * no helpers: C2 stops inlining ordinary calls in a method this large, and a call inside the
 * loop forces every vector to memory (see README.md).
 */
final class SatVector256 {
  static final double TOL = SeparatingAxisTest.CONTACT_TOLERANCE_MM, TOL2 = TOL * TOL, EPS = 1e-12;
  static final VectorSpecies<Double> S = DoubleVector.SPECIES_256;
  static final int L = 4;

  private SatVector256() {}

  /** Repacks flat boxes (15 doubles each, {@code Obb.writeTo} order) into the block layout. */
  static double[] layout(double[] a, double[] b, int n) {
    double[] d = new double[(n / L) * 30 * L];
    for (int blk = 0; blk < n / L; blk++) {
      for (int f = 0; f < 30; f++) {
        for (int l = 0; l < L; l++) {
          int pair = blk * L + l;
          d[(blk * 30 + f) * L + l] = f < 15 ? a[pair * 15 + f] : b[pair * 15 + f - 15];
        }
      }
    }
    return d;
  }

  /** out[i] = boxes of pair i overlap or touch; the last n % 4 pairs go through the scalar test. */
  static void kernel(double[] D, boolean[] out, int n, double[] a, double[] b) {
    int i=0; final DoubleVector ONE=DoubleVector.broadcast(S,1.0);
    for(; i<=n-L; i+=L){ final int o0=i*30;
      DoubleVector a00 = DoubleVector.fromArray(S, D, o0+24);
      DoubleVector a01 = DoubleVector.fromArray(S, D, o0+28);
      DoubleVector a02 = DoubleVector.fromArray(S, D, o0+32);
      DoubleVector a10 = DoubleVector.fromArray(S, D, o0+36);
      DoubleVector a11 = DoubleVector.fromArray(S, D, o0+40);
      DoubleVector a12 = DoubleVector.fromArray(S, D, o0+44);
      DoubleVector a20 = DoubleVector.fromArray(S, D, o0+48);
      DoubleVector a21 = DoubleVector.fromArray(S, D, o0+52);
      DoubleVector a22 = DoubleVector.fromArray(S, D, o0+56);
      DoubleVector b00 = DoubleVector.fromArray(S, D, o0+84);
      DoubleVector b01 = DoubleVector.fromArray(S, D, o0+88);
      DoubleVector b02 = DoubleVector.fromArray(S, D, o0+92);
      DoubleVector b10 = DoubleVector.fromArray(S, D, o0+96);
      DoubleVector b11 = DoubleVector.fromArray(S, D, o0+100);
      DoubleVector b12 = DoubleVector.fromArray(S, D, o0+104);
      DoubleVector b20 = DoubleVector.fromArray(S, D, o0+108);
      DoubleVector b21 = DoubleVector.fromArray(S, D, o0+112);
      DoubleVector b22 = DoubleVector.fromArray(S, D, o0+116);
      DoubleVector ea0 = DoubleVector.fromArray(S, D, o0+12);
      DoubleVector ea1 = DoubleVector.fromArray(S, D, o0+16);
      DoubleVector ea2 = DoubleVector.fromArray(S, D, o0+20);
      DoubleVector eb0 = DoubleVector.fromArray(S, D, o0+72);
      DoubleVector eb1 = DoubleVector.fromArray(S, D, o0+76);
      DoubleVector eb2 = DoubleVector.fromArray(S, D, o0+80);
      DoubleVector cax = DoubleVector.fromArray(S, D, o0+0);
      DoubleVector cay = DoubleVector.fromArray(S, D, o0+4);
      DoubleVector caz = DoubleVector.fromArray(S, D, o0+8);
      DoubleVector cbx = DoubleVector.fromArray(S, D, o0+60);
      DoubleVector cby = DoubleVector.fromArray(S, D, o0+64);
      DoubleVector cbz = DoubleVector.fromArray(S, D, o0+68);
      DoubleVector dx=cbx.sub(cax), dy=cby.sub(cay), dz=cbz.sub(caz);
      DoubleVector r00 = a00.mul(b00).add(a10.mul(b10)).add(a20.mul(b20));
      DoubleVector r01 = a00.mul(b01).add(a10.mul(b11)).add(a20.mul(b21));
      DoubleVector r02 = a00.mul(b02).add(a10.mul(b12)).add(a20.mul(b22));
      DoubleVector r10 = a01.mul(b00).add(a11.mul(b10)).add(a21.mul(b20));
      DoubleVector r11 = a01.mul(b01).add(a11.mul(b11)).add(a21.mul(b21));
      DoubleVector r12 = a01.mul(b02).add(a11.mul(b12)).add(a21.mul(b22));
      DoubleVector r20 = a02.mul(b00).add(a12.mul(b10)).add(a22.mul(b20));
      DoubleVector r21 = a02.mul(b01).add(a12.mul(b11)).add(a22.mul(b21));
      DoubleVector r22 = a02.mul(b02).add(a12.mul(b12)).add(a22.mul(b22));
      DoubleVector t0 = a00.mul(dx).add(a10.mul(dy)).add(a20.mul(dz));
      DoubleVector t1 = a01.mul(dx).add(a11.mul(dy)).add(a21.mul(dz));
      DoubleVector t2 = a02.mul(dx).add(a12.mul(dy)).add(a22.mul(dz));
      DoubleVector q00 = r00.abs().add(EPS);
      DoubleVector q01 = r01.abs().add(EPS);
      DoubleVector q02 = r02.abs().add(EPS);
      DoubleVector q10 = r10.abs().add(EPS);
      DoubleVector q11 = r11.abs().add(EPS);
      DoubleVector q12 = r12.abs().add(EPS);
      DoubleVector q20 = r20.abs().add(EPS);
      DoubleVector q21 = r21.abs().add(EPS);
      DoubleVector q22 = r22.abs().add(EPS);
      long sep = 0;
      sep |= (t0).abs().sub(ea0.add(eb0.mul(q00)).add(eb1.mul(q01)).add(eb2.mul(q02))).compare(VectorOperators.GT, TOL).toLong();
      sep |= (t1).abs().sub(ea1.add(eb0.mul(q10)).add(eb1.mul(q11)).add(eb2.mul(q12))).compare(VectorOperators.GT, TOL).toLong();
      sep |= (t2).abs().sub(ea2.add(eb0.mul(q20)).add(eb1.mul(q21)).add(eb2.mul(q22))).compare(VectorOperators.GT, TOL).toLong();
      sep |= (t0.mul(r00).add(t1.mul(r10)).add(t2.mul(r20))).abs().sub(ea0.mul(q00).add(ea1.mul(q10)).add(ea2.mul(q20)).add(eb0)).compare(VectorOperators.GT, TOL).toLong();
      sep |= (t0.mul(r01).add(t1.mul(r11)).add(t2.mul(r21))).abs().sub(ea0.mul(q01).add(ea1.mul(q11)).add(ea2.mul(q21)).add(eb1)).compare(VectorOperators.GT, TOL).toLong();
      sep |= (t0.mul(r02).add(t1.mul(r12)).add(t2.mul(r22))).abs().sub(ea0.mul(q02).add(ea1.mul(q12)).add(ea2.mul(q22)).add(eb2)).compare(VectorOperators.GT, TOL).toLong();
      { DoubleVector d=(t2.mul(r10).sub(t1.mul(r20))).abs().sub(ea1.mul(q20).add(ea2.mul(q10)).add(eb1.mul(q02)).add(eb2.mul(q01)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r00.mul(r00)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t2.mul(r11).sub(t1.mul(r21))).abs().sub(ea1.mul(q21).add(ea2.mul(q11)).add(eb0.mul(q02)).add(eb2.mul(q00)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r01.mul(r01)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t2.mul(r12).sub(t1.mul(r22))).abs().sub(ea1.mul(q22).add(ea2.mul(q12)).add(eb0.mul(q01)).add(eb1.mul(q00)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r02.mul(r02)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t0.mul(r20).sub(t2.mul(r00))).abs().sub(ea0.mul(q20).add(ea2.mul(q00)).add(eb1.mul(q12)).add(eb2.mul(q11)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r10.mul(r10)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t0.mul(r21).sub(t2.mul(r01))).abs().sub(ea0.mul(q21).add(ea2.mul(q01)).add(eb0.mul(q12)).add(eb2.mul(q10)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r11.mul(r11)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t0.mul(r22).sub(t2.mul(r02))).abs().sub(ea0.mul(q22).add(ea2.mul(q02)).add(eb0.mul(q11)).add(eb1.mul(q10)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r12.mul(r12)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t1.mul(r00).sub(t0.mul(r10))).abs().sub(ea0.mul(q10).add(ea1.mul(q00)).add(eb1.mul(q22)).add(eb2.mul(q21)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r20.mul(r20)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t1.mul(r01).sub(t0.mul(r11))).abs().sub(ea0.mul(q11).add(ea1.mul(q01)).add(eb0.mul(q22)).add(eb2.mul(q20)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r21.mul(r21)).mul(TOL2)).toLong(); }
      { DoubleVector d=(t1.mul(r02).sub(t0.mul(r12))).abs().sub(ea0.mul(q12).add(ea1.mul(q02)).add(eb0.mul(q21)).add(eb1.mul(q20)));
        sep |= d.compare(VectorOperators.GT, 0.0).toLong() & d.mul(d).compare(VectorOperators.GT, ONE.sub(r22.mul(r22)).mul(TOL2)).toLong(); }
      long bits = sep;
      for(int l=0;l<L;l++) out[i+l] = ((bits>>>l)&1L)==0;
    }
    for (; i < n; i++) {
      out[i] = SeparatingAxisTest.overlap(a, i, b, i);
    }
  }
}