package org.robotrun.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.robotrun.robot.RobotModel;

/**
 * The imports of {@code .urdf} files named directly as a scenario's robot model, kept for the
 * life of the process so that loading the scenario again (a reload, the window reopening the
 * cell, each command building its simulation from the scenario) does not import the file again.
 * An entry is used only while the SHA-256 of the URDF and of every mesh file it read is
 * unchanged, and the package folders are the same; otherwise the file is imported afresh.
 * Also remembers each URDF's package folders as a scenario gave them ({@code "packages"}), so
 * that later loads of the same file by path alone find them. At most {@link #MAX_ENTRIES}
 * imports are kept (least recently used first out). Thread-safe.
 */
public final class UrdfCache {
  /** Imports kept at most. */
  public static final int MAX_ENTRIES = 16;

  private record Kept(Map<String, Path> packages, byte[] digest, List<Path> files, RobotModel model) {}

  private static final Map<Path, Map<String, Path>> PACKAGES = new HashMap<>();
  private static final Map<Path, Kept> ENTRIES = new LinkedHashMap<>(16, 0.75f, true) {
    @Override
    protected boolean removeEldestEntry(Map.Entry<Path, Kept> eldest) {
      return size() > MAX_ENTRIES;
    }
  };
  private static int imports;

  private UrdfCache() {}

  /** Records the package folders a scenario gives for a URDF (absolute paths). */
  public static synchronized void rememberPackages(Path urdf, Map<String, Path> packages) {
    Path key = urdf.toAbsolutePath().normalize();
    if (packages.isEmpty()) {
      PACKAGES.remove(key);
    } else {
      PACKAGES.put(key, Map.copyOf(packages));
    }
  }

  /** The package folders last given for a URDF (empty: none; found by walking up). */
  public static synchronized Map<String, Path> packagesFor(Path urdf) {
    return PACKAGES.getOrDefault(urdf.toAbsolutePath().normalize(), Map.of());
  }

  /**
   * The robot of a URDF, imported with its remembered package folders, or the earlier import
   * when neither the URDF nor any mesh it read has changed.
   *
   * @throws FileFormatException as {@link UrdfImporter#importRobot}
   */
  public static synchronized RobotModel load(Path urdf) {
    Path key = urdf.toAbsolutePath().normalize();
    Map<String, Path> packages = packagesFor(key);
    Kept e = ENTRIES.get(key);
    if (e != null && e.packages().equals(packages)) {
      byte[] now = digest(key, e.files());
      if (now != null && Arrays.equals(now, e.digest())) {
        return e.model();
      }
    }
    UrdfImporter.Result r = UrdfImporter.importRobot(key, packages);
    imports++;
    byte[] d = digest(key, r.meshFiles());
    if (d != null) {
      ENTRIES.put(key, new Kept(packages, d, r.meshFiles(), r.model()));
    }
    return r.model();
  }

  /** How many imports {@link #load} has run in this process (for tests). */
  static synchronized int imports() {
    return imports;
  }

  /** SHA-256 over the URDF and the files, in order; null when one cannot be read. */
  private static byte[] digest(Path urdf, List<Path> files) {
    try {
      MessageDigest md = MessageDigest.getInstance("SHA-256");
      update(md, urdf);
      for (Path f : files) {
        md.update(f.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8));
        update(md, f);
      }
      return md.digest();
    } catch (IOException e) {
      return null;
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException("SHA-256 is missing from this Java", e);
    }
  }

  private static void update(MessageDigest md, Path f) throws IOException {
    byte[] buf = new byte[1 << 16];
    try (InputStream in = Files.newInputStream(f)) {
      for (int n; (n = in.read(buf)) > 0; ) {
        md.update(buf, 0, n);
      }
    }
  }
}
