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
    rows.add(String.format(Locale.ROOT, "  J1 %9.3f  J2 %9.3f  J3 %9.3f", j.j1Deg(), j.j2Deg(), j.j3Deg()));
    rows.add(String.format(Locale.ROOT, "  J4 %9.3f  J5 %9.3f  J6 %9.3f", j.j4Deg(), j.j5Deg(), j.j6Deg()));
    rows.add(" WORLD  Tool: " + ut + "   CONF: " + PositionScreen.config(w.config()));
    rows.addAll(cartesian(w));
    rows.add(" USER  Frame: " + uf + "  Tool: " + ut);
    rows.addAll(cartesian(u));
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
