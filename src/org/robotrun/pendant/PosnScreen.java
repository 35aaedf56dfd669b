package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;

/**
 * POSN: the current position, live: joints, the TCP of the active tool in WORLD, and in the
 * active user frame, with the frame numbers.
 */
final class PosnScreen implements Screen {
  @Override
  public String title(Pendant p) {
    return "POSITION  (live)";
  }

  @Override
  public List<String> body(Pendant p) {
    int ut = p.control().activeFrame(FrameKind.TOOL);
    int uf = p.control().activeFrame(FrameKind.USER);
    Position.Joint j = p.control().currentJoints();
    Position.Cartesian w = p.control().currentPose(0, ut);
    Position.Cartesian u = p.control().currentPose(uf, ut);
    List<String> rows = new ArrayList<>();
    rows.add(" JOINT (deg)");
    rows.addAll(jointRows(PositionScreen.jointLabels(p.control().jointNames()),
        new double[] {j.j1Deg(), j.j2Deg(), j.j3Deg(), j.j4Deg(), j.j5Deg(), j.j6Deg()}));
    rows.add(" WORLD  Tool: " + ut + "   CONF: " + PositionScreen.config(w.config()));
    rows.addAll(cartesian(w));
    rows.add(" USER  Frame: " + uf + "  Tool: " + ut);
    rows.addAll(cartesian(u));
    return rows;
  }

  /**
   * The joints in two rows of three, labelled as the robot file names them ("J1".."J6" on a
   * library arm, as on the controller); names too long for that take three rows of two.
   */
  static List<String> jointRows(List<String> labels, double[] deg) {
    int w = labels.stream().mapToInt(String::length).max().orElse(2);
    int perRow = w <= 9 ? 3 : 2;
    List<String> rows = new ArrayList<>();
    for (int i = 0; i < deg.length; i += perRow) {
      StringBuilder r = new StringBuilder();
      for (int k = i; k < Math.min(deg.length, i + perRow); k++) {
        r.append(String.format(Locale.ROOT, "  %-" + w + "s %9.3f", labels.get(k), deg[k]));
      }
      rows.add(r.toString());
    }
    return rows;
  }

  private static List<String> cartesian(Position.Cartesian c) {
    return List.of(
        String.format(Locale.ROOT, "  X %9.3f mm  Y %9.3f mm  Z %9.3f mm", c.xMm(), c.yMm(), c.zMm()),
        String.format(Locale.ROOT, "  W %9.3f deg P %9.3f deg R %9.3f deg", c.wDeg(), c.pDeg(), c.rDeg()));
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("", "", "", "", "");
  }

  @Override
  public void key(Pendant p, Key k) {
    p.message("POSN shows the live position; jog with SHIFT and the jog keys");
  }
}
