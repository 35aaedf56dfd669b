package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Rgb;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * Fixtures and parts as drawn (docs/scenario-format.md, "Where the origin is"): a box or cylinder
 * stands on its origin, the centre of its bottom face, so its drawn solid (centred on its frame)
 * sits half its height above the origin, turned with the object; a child is drawn where its parent
 * carries it; colours are the scenario's 0..255 values.
 */
class WorldDrawListTest {

  @Test
  void boxesAndCylindersStandOnTheirOriginInTheirColour() {
    Transform tablePose = Transform.translation(100, 50, -330).compose(Transform.rotation(0, 0, 1, Math.PI / 2));
    WorldObject table = WorldObject.of("table", ObjectKind.FIXTURE, new Shape.Box(600, 400, 230), new Rgb(255, 0, 51),
        tablePose, Optional.empty());
    WorldObject can = WorldObject.of("can", ObjectKind.PART, new Shape.Cylinder(20, 60), new Rgb(0, 128, 255),
        Transform.translation(10, 0, 230), Optional.of("table"));
    List<DrawItem> out = new ArrayList<>();
    WorldDrawList.addWorld(out, new World(List.of(table, can)));
    assertThat(out).extracting(DrawItem::name).containsExactly("table", "can");
    DrawItem t = out.get(0);
    assertThat(t.shape()).isEqualTo(new DrawShape.Box(new Vec3(600, 400, 230), false));
    // the box's centre: 115 mm above its bottom face's centre, along the table's own (turned) z
    Transform wantT = tablePose.compose(Transform.translation(0, 0, 115));
    assertThat(t.X_WS().distanceTo(wantT)).isLessThan(1e-9);
    assertThat(t.color()).isEqualTo(new DrawItem.Color(1f, 0f, 0.2f, 1f));
    DrawItem c = out.get(1);
    assertThat(c.shape()).isEqualTo(new DrawShape.Cylinder(20, 60));
    // on the table's top: the table's pose, then the can's pose in it, then half the can's height
    Transform wantC = tablePose.compose(Transform.translation(10, 0, 230)).compose(Transform.translation(0, 0, 30));
    assertThat(c.X_WS().distanceTo(wantC)).isLessThan(1e-9);
    assertThat(c.color().r()).isZero();
    assertThat(c.color().g()).isEqualTo(128 / 255f);
    assertThat(c.color().b()).isEqualTo(1f);
    assertThat(c.color().a()).isEqualTo(1f);
  }
}
