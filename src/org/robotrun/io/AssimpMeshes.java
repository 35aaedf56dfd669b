package org.robotrun.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.lwjgl.PointerBuffer;
import org.lwjgl.assimp.AIFace;
import org.lwjgl.assimp.AIMesh;
import org.lwjgl.assimp.AIScene;
import org.lwjgl.assimp.AIVector3D;
import org.lwjgl.assimp.Assimp;

/**
 * Reads the mesh files of imported robots (STL binary and ASCII, Wavefront OBJ, COLLADA .dae)
 * through LWJGL's binding of the Open Asset Import Library. The one class in {@code io} that
 * touches LWJGL (DESIGN.md allows it: a file reader, not a renderer).
 *
 * <p>Output is a triangle soup in the file's own frame with ROS's conventions: metres, z up.
 * STL and OBJ carry no units and are taken as metres (as ROS does). For COLLADA, Assimp applies
 * {@code <unit meter>} and turns the model so that its {@code <up_axis>} becomes Assimp's y-up
 * (both baked into the vertices here by {@code aiProcess_PreTransformVertices}); this class then
 * turns y-up back to z-up (+90° about x), so a Z_UP file comes out as written and a Y_UP file
 * stands up. {@code AssimpMeshesTest} checks both with hand-written files.
 */
public final class AssimpMeshes {
  /** Largest mesh file read (64 MiB, as for STL in scenarios). */
  public static final long MAX_FILE_BYTES = StlReader.MAX_FILE_BYTES;

  /** Most triangles accepted from one file. */
  public static final int MAX_TRIANGLES = StlReader.MAX_TRIANGLES;

  private AssimpMeshes() {}

  /** Whether {@code file}'s extension is one this reader takes. */
  public static boolean supports(String file) {
    String lower = file.toLowerCase(Locale.ROOT);
    return lower.endsWith(".stl") || lower.endsWith(".obj") || lower.endsWith(".dae");
  }

  /**
   * The triangles of {@code file}: 9 doubles per triangle, metres, z up.
   *
   * @throws FileFormatException the file is missing, too large, or Assimp cannot read it (its
   *     message says why)
   */
  public static double[] read(Path file) {
    String name = file.toString();
    try {
      if (!Files.isRegularFile(file)) {
        throw new FileFormatException(name, 0, "no such mesh file");
      }
      if (Files.size(file) > MAX_FILE_BYTES) {
        throw new FileFormatException(name, 0, "mesh file larger than " + (MAX_FILE_BYTES >> 20) + " MiB");
      }
    } catch (IOException e) {
      throw new FileFormatException(name, 0, "cannot read: " + e.getMessage());
    }
    int flags = Assimp.aiProcess_Triangulate | Assimp.aiProcess_PreTransformVertices | Assimp.aiProcess_SortByPType;
    AIScene scene = Assimp.aiImportFile(file.toAbsolutePath().toString(), flags);
    if (scene == null) {
      String why = Assimp.aiGetErrorString();
      throw new FileFormatException(name, 0, "not a readable mesh: "
          + (why == null || why.isBlank() ? "unknown format" : why.strip().replaceAll("\\s+", " ")));
    }
    try {
      boolean yUp = name.toLowerCase(Locale.ROOT).endsWith(".dae");
      int count = 0;
      PointerBuffer meshes = scene.mMeshes();
      int meshCount = scene.mNumMeshes();
      for (int m = 0; m < meshCount && meshes != null; m++) {
        AIMesh mesh = AIMesh.create(meshes.get(m));
        AIFace.Buffer faces = mesh.mFaces();
        for (int f = 0; f < mesh.mNumFaces(); f++) {
          if (faces.get(f).mNumIndices() == 3) {
            count++;
          }
        }
      }
      if (count == 0) {
        throw new FileFormatException(name, 0, "the mesh holds no triangles");
      }
      if (count > MAX_TRIANGLES) {
        throw new FileFormatException(name, 0, count + " triangles, more than the " + MAX_TRIANGLES + " accepted");
      }
      double[] out = new double[count * 9];
      int k = 0;
      for (int m = 0; m < meshCount; m++) {
        AIMesh mesh = AIMesh.create(meshes.get(m));
        AIVector3D.Buffer v = mesh.mVertices();
        AIFace.Buffer faces = mesh.mFaces();
        for (int f = 0; f < mesh.mNumFaces(); f++) {
          AIFace face = faces.get(f);
          if (face.mNumIndices() != 3) {
            continue;
          }
          for (int c = 0; c < 3; c++) {
            AIVector3D p = v.get(face.mIndices().get(c));
            double x = p.x(), y = p.y(), z = p.z();
            if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
              throw new FileFormatException(name, 0, "a vertex is not a finite number");
            }
            out[k++] = x;
            // Assimp's y-up back to ROS's z-up: (x, y, z) → (x, −z, y).
            out[k++] = yUp ? -z : y;
            out[k++] = yUp ? y : z;
          }
        }
      }
      return out;
    } finally {
      Assimp.aiReleaseImport(scene);
    }
  }
}
