package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/**
 * {@link LinkMesh} as documented: 9 floats per triangle or refused with the count found, the
 * triangles copied in (a caller's later writes do not reach it), equal when key, colour and every
 * float are equal (so a re-imported identical mesh is the same), and a short printed form.
 */
class LinkMeshTest {
  static final float[] ONE = {0, 0, 0, 10, 0, 0, 0, 10, 0};

  @Test
  void aMeshIsWholeTrianglesCopiedIn() {
    assertThatThrownBy(() -> new LinkMesh("k", new float[0], "body")).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("a link mesh needs 9 floats per triangle, got 0");
    assertThatThrownBy(() -> new LinkMesh("k", new float[10], "body")).hasMessageContaining("got 10");
    float[] two = new float[18];
    System.arraycopy(ONE, 0, two, 0, 9);
    LinkMesh m = new LinkMesh("k", two, "body");
    assertThat(m.triangleCount()).isEqualTo(2);
    two[0] = 99;
    assertThat(m.triangles()[0]).isZero();
    assertThat(m.toString()).isEqualTo("LinkMesh[k, 2 triangles, body]");
  }

  @Test
  void equalMeansSameKeyColourAndFloats() {
    LinkMesh a = new LinkMesh("arm.stl", ONE, "#598ccc");
    assertThat(a).isEqualTo(new LinkMesh("arm.stl", ONE.clone(), "#598ccc"));
    assertThat(a).hasSameHashCodeAs(new LinkMesh("arm.stl", ONE.clone(), "#598ccc"));
    assertThat(a).isNotEqualTo(new LinkMesh("other.stl", ONE, "#598ccc"));
    assertThat(a).isNotEqualTo(new LinkMesh("arm.stl", ONE, "body"));
    float[] moved = ONE.clone();
    moved[8] = 1;
    assertThat(a).isNotEqualTo(new LinkMesh("arm.stl", moved, "#598ccc"));
    assertThat(a).isNotEqualTo("arm.stl");
  }
}
