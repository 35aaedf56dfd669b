package org.robotrun.app;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.robotrun.grade.Task;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.Shape;
import org.robotrun.world.WorldObject;

/**
 * The files of an autograder bundle, by path inside it, and writing them as a {@code .zip} (Unix
 * permissions kept, so the scripts stay executable) or into a folder. Also gathers a task with
 * every file it needs (its scenario, the scenario's programs and meshes) under one folder, keeping
 * their relative places so the task's paths still hold.
 */
final class AutograderBundle {
  private static final Set<PosixFilePermission> EXECUTABLE = PosixFilePermissions.fromString("rwxr-xr-x");
  private static final Set<PosixFilePermission> PLAIN = PosixFilePermissions.fromString("rw-r--r--");

  /** One file: its bytes, or a file on disk to copy (the jar, a runtime). */
  private record Entry(byte[] bytes, Path source, boolean executable) {}

  private final Map<String, Entry> entries = new LinkedHashMap<>();

  void add(String path, byte[] bytes, boolean executable) {
    entries.put(path, new Entry(bytes, null, executable));
  }

  void add(String path, String text, boolean executable) {
    add(path, text.getBytes(StandardCharsets.UTF_8), executable);
  }

  void copy(String path, Path source, boolean executable) {
    entries.put(path, new Entry(null, source, executable));
  }

  /** Every file of a folder (a Java runtime), executables kept executable. */
  void copyTree(String prefix, Path dir) throws IOException {
    try (Stream<Path> s = Files.walk(dir)) {
      for (Path p : s.filter(Files::isRegularFile).sorted().toList()) {
        String rel = dir.relativize(p).toString().replace('\\', '/');
        copy(prefix + rel, p, Files.isExecutable(p));
      }
    }
  }

  List<String> paths() {
    return List.copyOf(entries.keySet());
  }

  /** Writes the bundle: a {@code .zip} when {@code out} ends so, else a folder; atomically replaced. */
  void write(Path out) throws IOException {
    Path target = out.toAbsolutePath();
    // Never replace a folder that holds anything: --out may name an instructor's course or a
    // template repository, and a bundle written over it would delete their files.
    if (Files.isDirectory(target, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
      try (Stream<Path> s = Files.list(target)) {
        if (s.findAny().isPresent()) {
          throw new UserError("--out " + out + ": the folder exists and is not empty; name a new folder"
              + " (its contents would be replaced) or remove it first");
        }
      }
    }
    Path dir = target.getParent();
    Files.createDirectories(dir);
    boolean zip = target.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".zip");
    Path temp = dir.resolve("." + target.getFileName() + ".tmp-" + ProcessHandle.current().pid());
    deleteTree(temp);
    try {
      if (zip) {
        writeZip(temp);
      } else {
        writeFolder(temp);
      }
      if (Files.isDirectory(target)) {
        deleteTree(target);
      }
      Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    } finally {
      deleteTree(temp);
    }
  }

  private void writeZip(Path file) throws IOException {
    // The JDK's zip file system stores POSIX permissions in the entries (a plain ZipOutputStream
    // cannot): Gradescope and unzip then keep run_autograder executable.
    URI uri = URI.create("jar:" + file.toUri());
    try (FileSystem fs = FileSystems.newFileSystem(uri, Map.of("create", "true", "enablePosixFileAttributes", "true"))) {
      for (Map.Entry<String, Entry> e : entries.entrySet()) {
        Path p = fs.getPath(e.getKey());
        if (p.getParent() != null) {
          Files.createDirectories(p.getParent());
        }
        put(e.getValue(), p);
        Files.setPosixFilePermissions(p, e.getValue().executable() ? EXECUTABLE : PLAIN);
      }
    }
  }

  private void writeFolder(Path dir) throws IOException {
    Files.createDirectories(dir);
    for (Map.Entry<String, Entry> e : entries.entrySet()) {
      Path p = dir.resolve(e.getKey());
      Files.createDirectories(p.getParent());
      put(e.getValue(), p);
      try {
        Files.setPosixFilePermissions(p, e.getValue().executable() ? EXECUTABLE : PLAIN);
      } catch (UnsupportedOperationException windows) {
        // no POSIX permissions here: the platform's own unpacking decides
      }
    }
  }

  private static void put(Entry e, Path p) throws IOException {
    if (e.bytes() != null) {
      Files.write(p, e.bytes());
    } else {
      Files.copy(e.source(), p, StandardCopyOption.REPLACE_EXISTING);
    }
  }

  static void deleteTree(Path p) throws IOException {
    if (!Files.exists(p, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
      return;
    }
    try (Stream<Path> s = Files.walk(p)) {
      for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
        Files.deleteIfExists(q);
      }
    }
  }

  /** A template from the jar's {@code /autograder/} resources, with {@code @KEY@} filled in. */
  static String template(String name, Map<String, String> values) {
    String text;
    try (InputStream in = AutograderBundle.class.getResourceAsStream("/autograder/" + name)) {
      if (in == null) {
        throw new IllegalStateException("the autograder template " + name + " is missing from the jar");
      }
      text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    for (Map.Entry<String, String> v : values.entrySet()) {
      text = text.replace("@" + v.getKey() + "@", v.getValue());
    }
    if (text.matches("(?s).*@[A-Z_]+@.*")) {
      throw new IllegalStateException("the autograder template " + name + " has a placeholder left");
    }
    return text;
  }

  /**
   * A task and the files it needs, under one folder: the task file, its scenario, the scenario's
   * programs and mesh files, each at its place relative to the folder that holds them all.
   *
   * @param task the task file's path inside that folder ({@code /}-separated)
   * @param files inside path to the file on disk
   */
  record TaskFiles(String task, Map<String, Path> files) {}

  /** Gathers a loaded task's files (see {@link TaskFiles}). */
  static TaskFiles gather(Path taskFile, TaskLoad.Loaded loaded) {
    Set<Path> all = new LinkedHashSet<>();
    all.add(taskFile.toAbsolutePath().normalize());
    all.add(loaded.task().scenario().toAbsolutePath().normalize());
    Scenario s = loaded.scenario();
    s.programs().forEach(p -> all.add(p.toAbsolutePath().normalize()));
    for (RobotSetup r : s.robots()) {
      r.programs().forEach(p -> all.add(p.toAbsolutePath().normalize()));
    }
    for (WorldObject o : s.world().objects()) {
      if (o.shape() instanceof Shape.Mesh m) {
        all.add(m.file().toAbsolutePath().normalize());
      }
    }
    Path common = null;
    for (Path p : all) {
      Path d = p.getParent();
      if (common == null) {
        common = d;
      } else {
        while (!d.startsWith(common)) {
          common = common.getParent();
        }
      }
    }
    Map<String, Path> files = new LinkedHashMap<>();
    for (Path p : all) {
      files.put(common.relativize(p).toString().replace('\\', '/'), p);
    }
    return new TaskFiles(common.relativize(all.iterator().next()).toString().replace('\\', '/'), files);
  }

  /**
   * Checks that the gathered files load on their own (nothing the scenario needs was left behind):
   * copies them into a temporary folder and reads the task there.
   *
   * @return the problems ("" when it loads)
   */
  static String verify(TaskFiles files) throws IOException {
    Path temp = Files.createTempDirectory("robotrun-bundle-");
    try {
      for (Map.Entry<String, Path> e : files.files().entrySet()) {
        Path p = temp.resolve(e.getKey());
        Files.createDirectories(p.getParent());
        Files.copy(e.getValue(), p);
      }
      return switch (TaskReader.read(temp.resolve(files.task()))) {
        case TaskLoad.Loaded l -> {
          // Every file the task reads must be the bundle's copy, not one named by an absolute path.
          List<String> outside = new ArrayList<>();
          List<Path> read = new ArrayList<>(List.of(l.task().scenario()));
          read.addAll(l.scenario().programs());
          l.scenario().robots().forEach(r -> read.addAll(r.programs()));
          l.scenario().world().objects().forEach(o -> {
            if (o.shape() instanceof Shape.Mesh m) {
              read.add(m.file());
            }
          });
          Path inside = temp.toRealPath();
          for (Path p : read) {
            if (!p.toAbsolutePath().normalize().startsWith(inside) && !p.toAbsolutePath().normalize().startsWith(temp)) {
              outside.add(p.toString());
            }
          }
          yield outside.isEmpty() ? "" : "named by an absolute path (make it relative to the file that names it): "
              + String.join(", ", outside);
        }
        case TaskLoad.Failed f -> f.message();
      };
    } finally {
      deleteTree(temp);
    }
  }

  /** The points of each check, as {@code runner:points} words for the GitHub script. */
  static String runnerWords(Task task) {
    List<String> names = PlatformResults.runnerNames(task);
    List<String> out = new ArrayList<>();
    for (int i = 0; i < names.size(); i++) {
      out.add(names.get(i) + ":" + GradeReports.fmt(task.checks().get(i).meta().points()));
    }
    return String.join(" ", out);
  }
}
