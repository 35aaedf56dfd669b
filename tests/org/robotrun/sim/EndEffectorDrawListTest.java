package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.EndEffectorGeometry;
import org.robotrun.world.EndEffectorType;

/**
 * The end effectors as drawn, against the table of docs/scenario-format.md (sizes in mm along
 * the flange's z axis): gripper body 50 × 100 from z 2 to 70 and fingers 20 × 10 × 50 from 70 to
 * 120, 70 mm apart open; suction stem Ø30 from 2 to 90 and cup Ø44 from 90 to the TCP at 110;
 * pointer holder Ø30 from 2 to 60, then the rod and its tip to the point at 150; glue gun body
 * 60 × 60 from 2 to 95 and nozzle Ø10 to the tip at 140; the bead of a glue trace a drop at
 * most 2 mm apart along each segment; a faceplate draws nothing. Every item follows the flange.
 */
class EndEffectorDrawListTest {
  /** A flange turned and moved: every item must follow it. */
  private static final Transform X_CF = Transform.translation(300, -40, 500).compose(Transform.rotation(1, 0, 0, Math.PI));

  /** One drawn solid: its extent along the flange's z axis and its cross-section. */
  private record Span(double z0, double z1, double sx, double sy) {}

  private static Map<String, Span> spans(EndEffectorType type, boolean on) {
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(type));
    s.setOn(on);
    List<DrawItem> out = new ArrayList<>();
    EndEffectorDrawList.add(out, s, X_CF);
    Map<String, Span> m = new LinkedHashMap<>();
    Transform X_FC = X_CF.inverse();
    for (DrawItem d : out) {
      Transform X_FS = X_FC.compose(d.X_WS());
      // each solid stands along the flange's z axis
      assertThat(X_FS.axis(2).z()).as(d.name()).isCloseTo(1, within(1e-9));
      double cz = X_FS.translationVector().z();
      Span sp = switch (d.shape()) {
        case DrawShape.Box b -> new Span(cz - b.size().z() / 2, cz + b.size().z() / 2, b.size().x(), b.size().y());
        case DrawShape.Cylinder c -> new Span(cz - c.length() / 2, cz + c.length() / 2, 2 * c.radius(), 2 * c.radius());
        default -> new Span(cz, cz, 0, 0); // the pointer's cone: its base at the frame
      };
      m.put(d.name(), sp);
    }
    return m;
  }

  private static void assertSpan(Span s, double z0, double z1, double sx, double sy) {
    assertThat(s.z0()).isCloseTo(z0, within(1e-9));
    assertThat(s.z1()).isCloseTo(z1, within(1e-9));
    assertThat(s.sx()).isCloseTo(sx, within(1e-9));
    assertThat(s.sy()).isCloseTo(sy, within(1e-9));
  }

  @Test
  void theGripperIsDrawnToItsDocumentedSizesWithTheFingersOpen() {
    Map<String, Span> m = spans(EndEffectorType.GRIPPER, false);
    assertSpan(m.get("robot1/tool/body"), 2, 70, 50, 100);
    assertThat(m).containsKeys("robot1/tool/plate", "robot1/tool/finger1", "robot1/tool/finger2");
    assertSpan(m.get("robot1/tool/finger1"), 70, 120, 20, 10);
    assertSpan(m.get("robot1/tool/finger2"), 70, 120, 20, 10);
    // open: 70 mm between the fingers' inner faces along the flange's y
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GRIPPER));
    List<DrawItem> out = new ArrayList<>();
    EndEffectorDrawList.add(out, s, X_CF);
    double y1 = X_CF.inverse().compose(out.get(2).X_WS()).translationVector().y();
    double y2 = X_CF.inverse().compose(out.get(3).X_WS()).translationVector().y();
    assertThat(Math.abs(y1 - y2) - 10).isCloseTo(70, within(1e-9));
  }

  @Test
  void theOtherToolsAreDrawnToTheirDocumentedSizes() {
    Map<String, Span> suction = spans(EndEffectorType.SUCTION, false);
    assertSpan(suction.get("robot1/tool/stem"), 2, 90, 30, 30);
    assertSpan(suction.get("robot1/tool/cup"), 90, 110, 44, 44);
    Map<String, Span> pointer = spans(EndEffectorType.POINTER, false);
    assertSpan(pointer.get("robot1/tool/holder"), 2, 60, 30, 30);
    // the rod (Ø8) runs from the holder to its tip, whose cone ends at the point (z = 150)
    Span rod = pointer.get("robot1/tool/rod");
    assertThat(rod.z0()).isCloseTo(60, within(1e-9));
    assertThat(rod.sx()).isCloseTo(8, within(1e-9));
    assertThat(pointer.get("robot1/tool/tip").z0()).isCloseTo(rod.z1(), within(1e-9));
    assertThat(rod.z1() + EndEffectorDrawList.POINTER_CONE_MM).isCloseTo(150, within(1e-9));
    Map<String, Span> glue = spans(EndEffectorType.GLUEGUN, false);
    assertSpan(glue.get("robot1/tool/body"), 2, 95, 60, 60);
    assertSpan(glue.get("robot1/tool/nozzle"), 95, 140, 10, 10);
    assertThat(spans(EndEffectorType.FACEPLATE, true)).isEmpty();
  }

  @Test
  void thePointersTipIsAConeFromTheRodsRadiusToThePoint() {
    DrawShape.Mesh cone = EndEffectorDrawList.cone("c", 4, 12, 24);
    float[] t = cone.triangles();
    assertThat(t).hasSize(24 * 2 * 9);
    double maxR = 0;
    double maxZ = 0;
    for (int i = 0; i < t.length; i += 3) {
      maxR = Math.max(maxR, Math.hypot(t[i], t[i + 1]));
      maxZ = Math.max(maxZ, t[i + 2]);
      assertThat((double) t[i + 2]).isBetween(0.0, 12.0);
    }
    assertThat(maxR).isCloseTo(4, within(1e-5));
    assertThat(maxZ).isCloseTo(12, within(1e-5));
    // the side triangles face outwards: their normal has a positive radial component
    for (int k = 0; k < 24; k++) {
      int o = k * 18;
      Vec3 a = new Vec3(t[o], t[o + 1], t[o + 2]);
      Vec3 b = new Vec3(t[o + 3], t[o + 4], t[o + 5]);
      Vec3 c = new Vec3(t[o + 6], t[o + 7], t[o + 8]);
      Vec3 n = b.minus(a).cross(c.minus(a));
      Vec3 mid = a.plus(b).times(0.5);
      assertThat(n.x() * mid.x() + n.y() * mid.y()).isPositive();
      // the base faces -z
      Vec3 a2 = new Vec3(t[o + 9], t[o + 10], t[o + 11]);
      Vec3 b2 = new Vec3(t[o + 12], t[o + 13], t[o + 14]);
      Vec3 c2 = new Vec3(t[o + 15], t[o + 16], t[o + 17]);
      assertThat(b2.minus(a2).cross(c2.minus(a2)).z()).isNegative();
    }
  }

  @Test
  void aTraceIsDrawnAsBeadsAtMostTwoMillimetresApartOnEachSegment() {
    List<EndEffectorState.TraceSegment> trace = List.of(
        new EndEffectorState.TraceSegment(new Vec3(0, 0, 0), new Vec3(5, 0, 0)),
        new EndEffectorState.TraceSegment(new Vec3(5, 0, 0), new Vec3(5, 0, 0)),
        new EndEffectorState.TraceSegment(new Vec3(5, 0, 0), new Vec3(5, 0, -4)));
    List<DrawItem> out = new ArrayList<>();
    EndEffectorDrawList.addTrace(out, "robot1/trace", trace);
    // 5 mm: 3 beads at 5/6, 15/6, 25/6; the empty segment none; 4 mm down: 2 beads at 1 and 3
    assertThat(out).hasSize(5);
    double[] xs = {5.0 / 6, 15.0 / 6, 25.0 / 6};
    for (int i = 0; i < 3; i++) {
      Vec3 c = out.get(i).X_WS().translationVector();
      assertThat(c.distanceTo(new Vec3(xs[i], 0, 0))).isLessThan(1e-9);
      // the bead lies along its segment
      assertThat(out.get(i).X_WS().axis(2).distanceTo(new Vec3(1, 0, 0))).isLessThan(1e-9);
    }
    assertThat(out.get(3).X_WS().translationVector().distanceTo(new Vec3(5, 0, -1))).isLessThan(1e-9);
    assertThat(out.get(4).X_WS().translationVector().distanceTo(new Vec3(5, 0, -3))).isLessThan(1e-9);
    assertThat(out.get(4).X_WS().axis(2).distanceTo(new Vec3(0, 0, -1))).isLessThan(1e-9);
    assertThat(out).allMatch(d -> d.name().equals("robot1/trace") && d.color().equals(EndEffectorDrawList.BEAD));
    // a glue gun draws its trace after its body and nozzle
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GLUEGUN));
    s.setOn(true);
    s.extendTrace(new Vec3(0, 0, 0));
    s.extendTrace(new Vec3(0, 2, 0));
    List<DrawItem> gun = new ArrayList<>();
    EndEffectorDrawList.add(gun, s, X_CF);
    assertThat(gun).extracting(DrawItem::name).containsExactly("robot1/tool/body", "robot1/tool/nozzle", "robot1/trace");
  }

  @Test
  void alongZTurnsZOntoAnyDirection() {
    for (Vec3 d : List.of(new Vec3(0, 0, 1), new Vec3(0, 0, -1), new Vec3(1, 0, 0), new Vec3(0, -1, 0),
        new Vec3(0.6, 0, 0.8), new Vec3(-0.48, 0.6, -0.64))) {
      Transform r = EndEffectorDrawList.alongZ(d);
      assertThat(r.axis(2).distanceTo(d)).as("%s", d).isLessThan(1e-9);
      assertThat(r.axis(0).cross(r.axis(1)).distanceTo(d)).as("%s", d).isLessThan(1e-9);
      assertThat(r.translationVector().norm()).isZero();
    }
  }
}
