package org.robotrun.io;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.SecureRandom;
import java.util.Comparator;
import java.util.stream.Stream;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.robot.JointSpec;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/**
 * Writes a robot as a RobotRun robot folder: {@code ID.json} (the format of
 * {@code resources/robots/}, see docs/architecture.md) and {@code meshes/LINK_K.stl} (binary
 * STL, mm, link frame) for its display meshes. All or nothing: the folder is filled under a
 * temporary name beside it and renamed into place; on any failure the temporary folder is
 * removed and nothing is left.
 */
public final class RobotFileWriter {
  private static final ObjectMapper JSON = new ObjectMapper();
  private static final SecureRandom RANDOM = new SecureRandom();

  private RobotFileWriter() {}

  /**
   * Writes {@code model} into the new folder {@code outDir} (which must not exist, or be empty).
   *
   * @param sourceNote the definition's {@code source} text (where it came from)
   * @return the robot file, {@code outDir/ID.json}
   * @throws FileFormatException naming {@code outDir} when it exists with files in it
   */
  public static Path write(RobotModel model, String sourceNote, Path outDir) throws IOException {
    Path out = outDir.toAbsolutePath().normalize();
    if (Files.exists(out) && !isEmptyFolder(out)) {
      throw new FileFormatException(outDir.toString(), 0, "already exists and is not an empty folder: choose a new --out folder");
    }
    Path parent = out.getParent();
    Files.createDirectories(parent);
    Path tmp = parent.resolve("." + out.getFileName() + ".import-" + Long.toHexString(RANDOM.nextLong()));
    Files.createDirectory(tmp);
    try {
      Path meshes = tmp.resolve("meshes");
      ObjectNode root = JSON.createObjectNode();
      root.put("format", 1);
      root.put("id", model.id());
      root.put("name", model.displayName());
      root.put("source", sourceNote);
      ObjectNode units = root.putObject("units");
      units.put("length", "mm");
      units.put("angle", "deg");
      root.put("coupledJ3", model.coupledJ3());
      if (model.maxLinearSpeedMmPerSec() != RobotModel.DEFAULT_MAX_LINEAR_SPEED_MM_PER_SEC) {
        root.put("maxLinearSpeed", model.maxLinearSpeedMmPerSec());
      }
      ObjectNode wib = root.putObject("worldInBase");
      wib.put("x", -model.X_WB().x());
      wib.put("y", -model.X_WB().y());
      wib.put("z", -model.X_WB().z());
      ArrayNode joints = root.putArray("joints");
      for (JointSpec j : model.joints()) {
        ObjectNode n = joints.addObject();
        n.put("name", j.name());
        pose(n, j.X_PJ());
        ArrayNode axis = n.putArray("axis");
        axis.add(j.axis().x()).add(j.axis().y()).add(j.axis().z());
        n.put("lower", Math.toDegrees(j.lowerRad()));
        n.put("upper", Math.toDegrees(j.upperRad()));
        n.put("maxSpeed", Math.toDegrees(j.maxSpeedRadPerSec()));
      }
      pose(root.putObject("flange"), model.X_6F());
      ArrayNode links = root.putArray("links");
      for (LinkSpec l : model.links()) {
        ObjectNode n = links.addObject();
        n.put("name", l.name());
        ArrayNode shapes = n.putArray("shapes");
        for (LinkShape s : l.shapes()) {
          ObjectNode sn = shapes.addObject();
          switch (s) {
            case LinkShape.Box b -> {
              sn.put("type", "box");
              pose(sn, b.X_LS());
              sn.putArray("size").add(b.size().x()).add(b.size().y()).add(b.size().z());
            }
            case LinkShape.Cylinder c -> {
              sn.put("type", "cylinder");
              pose(sn, c.X_LS());
              sn.put("radius", c.radius());
              sn.put("length", c.length());
            }
          }
          sn.put("color", s.color());
        }
        if (!l.meshes().isEmpty()) {
          Files.createDirectories(meshes);
          ArrayNode ms = n.putArray("meshes");
          int k = 0;
          for (LinkMesh m : l.meshes()) {
            String file = "meshes/" + l.name().replaceAll("[^A-Za-z0-9_.-]", "_") + "_" + k++ + ".stl";
            AtomicFiles.writeLeavingFolderSync(tmp.resolve(file), binaryStl(m.triangles()));
            ObjectNode mn = ms.addObject();
            mn.put("file", file);
            mn.put("color", m.color());
          }
        }
      }
      Path json = tmp.resolve(model.id() + ".json");
      AtomicFiles.writeLeavingFolderSync(json, JSON.writerWithDefaultPrettyPrinter().writeValueAsBytes(root));
      if (Files.isDirectory(meshes)) {
        AtomicFiles.syncFolder(meshes);
      }
      AtomicFiles.syncFolder(tmp);
      if (Files.exists(out)) {
        Files.delete(out);
      }
      try {
        Files.move(tmp, out, StandardCopyOption.ATOMIC_MOVE);
      } catch (FileAlreadyExistsException e) {
        throw new FileFormatException(outDir.toString(), 0, "appeared while importing: choose a new --out folder");
      }
      AtomicFiles.syncFolder(parent);
      return out.resolve(model.id() + ".json");
    } catch (IOException | RuntimeException e) {
      deleteTree(tmp);
      throw e;
    }
  }

  /** "xyz" (mm) and "rpy" (deg, R = Rz·Ry·Rx) of a pose. */
  private static void pose(ObjectNode n, Transform X) {
    Xyzwpr p = Xyzwpr.fromTransform(X);
    n.putArray("xyz").add(X.x()).add(X.y()).add(X.z());
    n.putArray("rpy").add(p.wDeg()).add(p.pDeg()).add(p.rDeg());
  }

  static byte[] binaryStl(float[] t) {
    int n = t.length / 9;
    ByteBuffer b = ByteBuffer.allocate(84 + 50 * n).order(ByteOrder.LITTLE_ENDIAN);
    byte[] header = "RobotRun display mesh, mm, link frame".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    b.put(header);
    b.position(80);
    b.putInt(n);
    for (int i = 0; i < t.length; i += 9) {
      float ux = t[i + 3] - t[i], uy = t[i + 4] - t[i + 1], uz = t[i + 5] - t[i + 2];
      float vx = t[i + 6] - t[i], vy = t[i + 7] - t[i + 1], vz = t[i + 8] - t[i + 2];
      float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      float len = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
      if (len > 0) {
        nx /= len;
        ny /= len;
        nz /= len;
      }
      b.putFloat(nx).putFloat(ny).putFloat(nz);
      for (int c = 0; c < 9; c++) {
        b.putFloat(t[i + c]);
      }
      b.putShort((short) 0);
    }
    return b.array();
  }

  private static boolean isEmptyFolder(Path dir) throws IOException {
    if (!Files.isDirectory(dir)) {
      return false;
    }
    try (Stream<Path> s = Files.list(dir)) {
      return s.findAny().isEmpty();
    }
  }

  private static void deleteTree(Path dir) {
    try (Stream<Path> s = Files.walk(dir)) {
      for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
        Files.deleteIfExists(p);
      }
    } catch (IOException e) {
      // Best effort: the folder's name starts with a dot and says what it was.
    }
  }
}
