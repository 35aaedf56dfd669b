package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.pendant.Pendant;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.DrawItem;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.sim.Simulation;

/** In a cell of several robots the driven one is marked in the scene, on a label and on the pendant's status line. */
class DrivenRobotMarkTest {
  private final Simulation two = new Simulation(List.of(DefaultCell.controller(RobotDefinitions.defaultRobot(), "robot1"),
      DefaultCell.controller(RobotDefinitions.defaultRobot(), "robot2")),
      List.of(Transform.IDENTITY, Transform.translation(1500, 0, 0)), new org.robotrun.world.World(List.of()), 0,
      Simulation.DEFAULT_TICK_SEC);

  @Test
  void onlyTheDrivenRobotsBodiesAreTintedTowardTheMarkColour() {
    SceneSnapshot scene = two.snapshot().scene();
    SceneSnapshot marked = DrivenRobotMark.tinted(scene, "robot2", 2);
    // one more item: the disc around the driven robot's foot, centred under its base (robot2 stands at x 1500)
    assertThat(marked.items()).hasSize(scene.items().size() + 1);
    DrawItem ring = marked.items().get(scene.items().size());
    assertThat(ring.name()).isEqualTo(DrivenRobotMark.RING_NAME);
    assertThat(ring.X_WS().x()).isCloseTo(1500, org.assertj.core.data.Offset.offset(1.0));
    assertThat(ring.X_WS().y()).isCloseTo(0, org.assertj.core.data.Offset.offset(1.0));
    int tinted = 0;
    for (int i = 0; i < scene.items().size(); i++) {
      DrawItem a = scene.items().get(i), b = marked.items().get(i);
      assertThat(b.name()).isEqualTo(a.name());
      assertThat(b.X_WS()).isEqualTo(a.X_WS());
      if (a.name().startsWith("robot2/")) {
        tinted++;
        // nearer the amber in every channel that was not already amber
        assertThat(Math.abs(b.color().r() - DrivenRobotMark.R)).isLessThanOrEqualTo(Math.abs(a.color().r() - DrivenRobotMark.R));
        assertThat(Math.abs(b.color().b() - DrivenRobotMark.B)).isLessThanOrEqualTo(Math.abs(a.color().b() - DrivenRobotMark.B));
        assertThat(b.color()).isNotEqualTo(a.color());
        assertThat(b.color().a()).isEqualTo(a.color().a());
      } else {
        assertThat(b).isSameAs(a);
      }
    }
    assertThat(tinted).isGreaterThan(5);
  }

  @Test
  void aCellOfOneRobotIsNotMarked() {
    SceneSnapshot scene = two.snapshot().scene();
    assertThat(DrivenRobotMark.tinted(scene, "robot1", 1)).isSameAs(scene);
    assertThat(DrivenRobotMark.tinted(scene, "", 2)).isSameAs(scene);
  }

  @Test
  void theLabelSitsBesideTheBaseOffTheWorkAndInsideTheView() {
    // a part just right of the base and one left of it: the label goes above or below
    List<LabelLayout.Box> work = List.of(new LabelLayout.Box(410, 280, 120, 60), new LabelLayout.Box(250, 280, 140, 60));
    LabelLayout.Placed p = DrivenRobotMark.labelPlace(400, 300, 60, 20, 800, 600, work).orElseThrow();
    for (LabelLayout.Box w : work) {
      assertThat(p.box().overlaps(w)).isFalse();
    }
    assertThat(p.box().inside(800, 600)).isTrue();
    assertThat(p.box().distanceTo(400, 300)).isLessThan(40);
    // the table the cell stands on covers most of the view: it is the room, not the work
    LabelLayout.Placed onTable = DrivenRobotMark.labelPlace(400, 300, 60, 20, 800, 600,
        List.of(new LabelLayout.Box(0, 200, 800, 400))).orElseThrow();
    assertThat(onTable.leader()).isFalse();
    // a base off the view gets no label
    assertThat(DrivenRobotMark.labelPlace(900, 300, 60, 20, 800, 600, List.of())).isEmpty();
  }

  @Test
  void thePendantsStatusLineStartsWithTheDrivenRobotsName() {
    // PendantPanel paints the name's cells in the mark's colour; here: the name is where it paints
    Pendant p = new Pendant(new ControllerPort(two.controllers().get(1)));
    p.setRobotLabel("robot2");
    assertThat(p.lcd().row(0)).startsWith("robot2 ");
    Pendant single = new Pendant(new ControllerPort(two.controllers().get(0)));
    assertThat(single.robotLabel()).isEmpty();
  }
}
