package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;

/**
 * The CRX's CONFIG flags against the definitions of docs/kinematics.md (ChainConfig), worked out by
 * hand for the CRX chain read here from resources/robots/ID.json with a plain JSON parser: J1 about
 * z, J2 about y through J1's axis, the upper arm L2 up to J3 (about −y), the forearm L3 along x to
 * the wrist point W (J5's origin, on J4's axis). With the upper arm at angle q2 and the forearm at
 * q2 − q3 about y, W lies L2·sin q2 + L3·cos(q2 − q3) in front of the J1 axis (T when positive);
 * (elbow − shoulder) × (W − elbow) is L2·L3·cos q3 along the arm plane's normal y (U when
 * positive); F when J5 &gt; 0; turn numbers of J1, J4, J6 by Config.turnOf. J1, J4 and J6 change no
 * flag. A teacher's usual posture (J2 = J3 = 0, J5 = −90°) is 'N U T, 0, 0, 0'.
 */
class CrxConfigTruthTableTest {

  static JsonNode file(String id) throws Exception {
    return new ObjectMapper().readTree(Files.readString(Path.of("resources/robots/" + id + ".json")));
  }

  static double[] xyz(JsonNode j) {
    return new double[] {j.get("xyz").get(0).asDouble(), j.get("xyz").get(1).asDouble(), j.get("xyz").get(2).asDouble()};
  }

  @ParameterizedTest
  @ValueSource(strings = {"crx10ia", "crx10ial"})
  void theFlagsAreTheWristPointsSideAndTheElbowsBend(String id) throws Exception {
    JsonNode joints = file(id).get("joints");
    // The chain is as described above (else the hand derivation does not apply).
    assertThat(xyz(joints.get(1))).containsExactly(0, 0, 0);
    assertThat(xyz(joints.get(3))).containsExactly(0, 0, 0);
    assertThat(joints.get(1).get("axis").toString()).isEqualTo("[0,1,0]");
    assertThat(joints.get(2).get("axis").toString()).isEqualTo("[0,-1,0]");
    double l2 = xyz(joints.get(2))[2];
    double l3 = xyz(joints.get(4))[0];
    assertThat(xyz(joints.get(2))[0]).isZero();
    assertThat(xyz(joints.get(4))[2]).isZero();
    RobotModel m = RobotDefinitions.load(id);
    IkSolver ik = IkSolver.forModel(m);
    assertThat(ik.kind()).isEqualTo(OffsetWristIk.KIND);
    assertThat(ik.configOf(new double[] {0, 0, 0, 0, Math.toRadians(-90), 0}).toString()).isEqualTo("N U T, 0, 0, 0");
    Random rnd = new Random(id.length() * 31L);
    int[] seen = new int[8];
    for (int k = 0; k < 400; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = m.joint(i).lowerRad() + rnd.nextDouble() * (m.joint(i).upperRad() - m.joint(i).lowerRad());
      }
      double front = l2 * Math.sin(q[1]) + l3 * Math.cos(q[1] - q[2]);
      double bend = Math.cos(q[2]);
      if (Math.abs(front) < 1 || Math.abs(bend) < 1e-3 || Math.abs(q[4]) < 1e-6) {
        continue;
      }
      Config c = ik.configOf(q);
      String what = id + " " + java.util.Arrays.toString(q);
      assertThat(c.top()).as("%s T", what).isEqualTo(front > 0);
      assertThat(c.up()).as("%s U", what).isEqualTo(bend > 0);
      assertThat(c.flip()).as("%s F", what).isEqualTo(ClosedFormIk.wrap(q[4]) > 0);
      assertThat(new int[] {c.turn1(), c.turn4(), c.turn6()})
          .containsExactly(Config.turnOf(q[0]), Config.turnOf(q[3]), Config.turnOf(q[5]));
      seen[(c.flip() ? 4 : 0) + (c.up() ? 2 : 0) + (c.top() ? 1 : 0)]++;
    }
    assertThat(seen).as("every flag triple met").doesNotContain(0);
  }
}
