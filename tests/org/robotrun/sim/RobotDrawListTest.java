package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/** A link with display meshes is drawn from them; a link without is drawn from its shapes. */
class RobotDrawListTest {

  @Test
  void meshesReplaceTheShapesOfTheirLinkOnly() {
    RobotModel lr = RobotDefinitions.defaultRobot();
    float[] tri = {0, 0, 0, 10, 0, 0, 0, 10, 0};
    List<LinkSpec> links = new ArrayList<>(lr.links());
    LinkSpec l3 = links.get(3);
    links.set(3, new LinkSpec(l3.name(), l3.shapes(), List.of(new LinkMesh("m3", tri, "#ff8000"))));
    RobotModel m = new RobotModel("meshy", "meshy", lr.joints(), lr.X_6F(), lr.X_WB(), links, lr.opw(), lr.coupledJ3());
    double[] q = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    List<DrawItem> items = new ArrayList<>();
    RobotDrawList.addRobot(items, "r", m, Transform.IDENTITY, q);
    List<DrawItem> link3 = items.stream().filter(i -> i.name().equals("r/" + l3.name())).toList();
    assertThat(link3).singleElement().satisfies(i -> {
      assertThat(i.shape()).isInstanceOf(DrawShape.Mesh.class);
      assertThat(((DrawShape.Mesh) i.shape()).triangles()).containsExactly(tri);
      assertThat(i.X_WS()).isEqualTo(ForwardKinematics.linkPosesInWorld(m, q)[3]);
      assertThat(i.color()).isEqualTo(DrawItem.Color.rgb(1, 128 / 255.0, 0));
    });
    long shapes = lr.links().stream().mapToLong(l -> l.shapes().size()).sum();
    assertThat(items).hasSize((int) (shapes - l3.shapes().size() + 1));
    assertThat(items.stream().filter(i -> i.name().equals("r/" + links.get(2).name())))
        .allMatch(i -> !(i.shape() instanceof DrawShape.Mesh));
  }

  @Test
  void linkShapesStayTheCollisionBodiesOfAMeshLink() {
    LinkSpec l = new LinkSpec("l", List.of(new LinkShape.Box(Transform.IDENTITY, new Vec3(1, 2, 3), "body")),
        List.of(new LinkMesh("k", new float[9], "body")));
    assertThat(l.shapes()).hasSize(1);
    assertThat(l.meshes()).hasSize(1);
  }
}
