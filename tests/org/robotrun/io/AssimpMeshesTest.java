package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Mesh files of every format read by Assimp come out in metres with z up. */
class AssimpMeshesTest {
  @TempDir Path dir;

  // An off-centre box, tall along z in the frame the numbers are written in.
  private static final double[] LO = {0.1, 0.2, 0.3};
  private static final double[] HI = {0.15, 0.3, 0.7};

  @Test
  void stlAsciiStlBinaryAndObjKeepTheirCoordinates() throws Exception {
    double[] box = MeshFiles.box(LO, HI);
    MeshFiles.stlAscii(dir.resolve("a.stl"), box);
    MeshFiles.stlBinary(dir.resolve("b.STL"), box);
    MeshFiles.obj(dir.resolve("c.obj"), box);
    for (String f : new String[] {"a.stl", "b.STL", "c.obj"}) {
      double[] t = AssimpMeshes.read(dir.resolve(f));
      assertThat(t).hasSize(12 * 9);
      assertBounds(t, LO, HI, 1e-6);
    }
  }

  // Method: the same box written as a Z_UP file in metres and as a Y_UP file in millimetres
  // (its z coordinates written as y, its y as -z); both must read back as the box in metres,
  // z up. Tolerance 1e-6 m.
  @Test
  void colladaUnitAndUpAxisAreHonoured() throws Exception {
    double[] box = MeshFiles.box(LO, HI);
    MeshFiles.dae(dir.resolve("z.dae"), box, 1.0, "Z_UP");
    assertBounds(AssimpMeshes.read(dir.resolve("z.dae")), LO, HI, 1e-6);

    double[] yUpMm = new double[box.length];
    for (int i = 0; i < box.length; i += 3) {
      yUpMm[i] = box[i] * 1000;
      yUpMm[i + 1] = box[i + 2] * 1000;
      yUpMm[i + 2] = -box[i + 1] * 1000;
    }
    MeshFiles.dae(dir.resolve("y.dae"), yUpMm, 0.001, "Y_UP");
    assertBounds(AssimpMeshes.read(dir.resolve("y.dae")), LO, HI, 1e-6);

    double[] inches = new double[box.length];
    for (int i = 0; i < box.length; i++) {
      inches[i] = box[i] / 0.0254;
    }
    MeshFiles.dae(dir.resolve("in.dae"), inches, 0.0254, "Z_UP");
    assertBounds(AssimpMeshes.read(dir.resolve("in.dae")), LO, HI, 1e-6);
  }

  // Method: the box at the origin placed by its node's matrix (a translation of 1, 2, 3 units
  // in a file in centimetres, Z_UP): the vertices come out moved by 0.01, 0.02, 0.03 m.
  @Test
  void colladaNodeTransformsAreBakedIn() throws Exception {
    double[] cm = MeshFiles.box(new double[] {0, 0, 0}, new double[] {10, 20, 30});
    MeshFiles.dae(dir.resolve("node.dae"), cm, 0.01, "Z_UP", "<matrix>1 0 0 1 0 1 0 2 0 0 1 3 0 0 0 1</matrix>");
    assertBounds(AssimpMeshes.read(dir.resolve("node.dae")), new double[] {0.01, 0.02, 0.03}, new double[] {0.11, 0.22, 0.33}, 1e-6);
  }

  // An OBJ as CAD tools export it: quads, a material library that was not copied along.
  @Test
  void objWithQuadsAndAMissingMaterialLibraryReads() throws Exception {
    Files.writeString(dir.resolve("q.obj"), """
        mtllib gone.mtl
        v 0 0 0
        v 0.1 0 0
        v 0.1 0.2 0
        v 0 0.2 0
        v 0 0 0.3
        usemtl paint
        f 1 2 3 4
        f 1 2 5
        """);
    double[] t = AssimpMeshes.read(dir.resolve("q.obj"));
    assertThat(t).hasSize(3 * 9);
    assertBounds(t, new double[] {0, 0, 0}, new double[] {0.1, 0.2, 0.3}, 1e-6);
  }

  @Test
  void aFileThatIsNotAMeshIsRefusedWithItsName() throws Exception {
    Path bad = dir.resolve("bad.stl");
    Files.writeString(bad, "this is not a mesh");
    assertThatThrownBy(() -> AssimpMeshes.read(bad)).isInstanceOf(FileFormatException.class).hasMessageContaining("bad.stl");
    assertThatThrownBy(() -> AssimpMeshes.read(dir.resolve("missing.dae")))
        .isInstanceOf(FileFormatException.class).hasMessageContaining("missing.dae").hasMessageContaining("no such mesh file");
  }

  private static void assertBounds(double[] t, double[] lo, double[] hi, double tol) {
    double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
    double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
    for (int i = 0; i < t.length; i++) {
      min[i % 3] = Math.min(min[i % 3], t[i]);
      max[i % 3] = Math.max(max[i % 3], t[i]);
    }
    for (int k = 0; k < 3; k++) {
      assertThat(min[k]).as("min[%d]", k).isCloseTo(lo[k], within(tol));
      assertThat(max[k]).as("max[%d]", k).isCloseTo(hi[k], within(tol));
    }
  }
}
