package org.robotrun.robot;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

class CrxDebugTest {
  @Test
  void dbg() {
    for (String id : List.of("crx10ia", "crx10ial")) {
      RobotModel model = RobotDefinitions.load(id);
      OffsetWristIk ik = new OffsetWristIk(model);
      int idx = id.equals("crx10ia") ? 105 : 263;
      double[] q = RobotLibraryTest.randomJoints(model, RobotLibraryTest.FACTS.get(id), 2000, 1000 + id.hashCode()).get(idx);
      Transform X = ForwardKinematics.flangePoseInBase(model, q);
      System.out.println(id + " q=" + java.util.Arrays.toString(q) + " t=" + ik.angleOf(q) + " " + ik.configOf(q));
      for (double[] s : ik.baseSolutions(X)) {
        System.out.println("  sol " + java.util.Arrays.toString(s) + " t=" + ik.angleOf(s) + " " + ik.configOf(s));
      }
      ik.baseSolutions(X);
      System.out.println("  roots " + java.util.Arrays.toString(ik.lastRoots()));
      double[] g = ik.gCurve(X, 720);
      double[] f = ik.gCurve(X, 64);
      for (int h = 0; h <= 12; h++) {
        double re = 0, im = 0;
        for (int k = 0; k < 64; k++) { re += f[k] * Math.cos(h * k * 2 * Math.PI / 64); im += f[k] * Math.sin(h * k * 2 * Math.PI / 64); }
        System.out.println("   harmonic " + h + " " + Math.hypot(re, im) / 64);
      }
      double t = ik.angleOf(q);
      int k0 = (int) Math.round(t / (2 * Math.PI) * 720);
      for (int k = k0 - 8; k <= k0 + 8; k++) {
        System.out.println("   g[" + k + "]=" + g[(k + 720) % 720]);
      }
    }
  }
}
