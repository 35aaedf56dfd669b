package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.RobotFileWriter;
import org.robotrun.io.UrdfImporter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code robotrun bench import FILE.urdf}: how long a URDF import takes, cold and warm. */
@Command(
    name = "import",
    mixinStandardHelpOptions = true,
    description = {
      "Time 'robot import' on a URDF.",
      "The first import in this JVM (cold: classes and Assimp's native library load), then the median of --rounds imports and of as many robot folder writes (to a temporary folder, removed). Prints wall and CPU milliseconds (CPU time of this thread, which other processes do not inflate), triangles and fitted boxes."
    })
final class BenchImportCommand implements Callable<Integer> {
  @Spec picocli.CommandLine.Model.CommandSpec spec;

  @Parameters(index = "0", paramLabel = "FILE.urdf", description = "The URDF file.")
  Path urdf;

  @Option(names = "--package", paramLabel = "NAME=DIR", description = "Where package NAME is (repeatable).")
  List<String> packages = List.of();

  @Option(names = "--rounds", paramLabel = "N", defaultValue = "10", description = "Timed imports after the first (default: ${DEFAULT-VALUE}).")
  int rounds;

  @Override
  public Integer call() throws IOException {
    if (rounds < 1) {
      throw new UserError("--rounds must be at least 1");
    }
    Map<String, Path> dirs = RobotImportCommand.packageDirs(packages);
    long w0 = BenchClock.WALL.nanos();
    long c0 = BenchClock.CPU.nanos();
    UrdfImporter.Result first;
    try {
      first = UrdfImporter.importRobot(urdf, dirs);
    } catch (FileFormatException e) {
      throw new UserError(e.getMessage(), Main.EXIT_BAD_INPUT);
    }
    double coldWall = (BenchClock.WALL.nanos() - w0) / 1e6;
    double coldCpu = (BenchClock.CPU.nanos() - c0) / 1e6;
    long importWall = BenchClock.WALL.medianNanos(rounds, () -> UrdfImporter.importRobot(urdf, dirs));
    long importCpu = BenchClock.CPU.medianNanos(rounds, () -> UrdfImporter.importRobot(urdf, dirs));
    Path tmp = Files.createTempDirectory("robotrun-bench-import");
    long writeWall;
    try {
      int[] n = {0};
      writeWall = BenchClock.WALL.medianNanos(rounds, () -> {
        try {
          RobotFileWriter.write(first.model(), "bench", tmp.resolve("r" + n[0]++));
        } catch (IOException e) {
          throw new UserError("cannot write to " + tmp + ": " + e.getMessage(), Main.EXIT_FAILED);
        }
      });
    } finally {
      try (Stream<Path> s = Files.walk(tmp)) {
        for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
          Files.deleteIfExists(p);
        }
      }
    }
    int triangles = first.model().links().stream().flatMap(l -> l.meshes().stream()).mapToInt(m -> m.triangleCount()).sum();
    long fitted = first.bodies().stream().filter(b -> !Double.isNaN(b.hullVolumeMm3())).count();
    PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT, "robot=%s triangles=%d fitted_boxes=%d cold_import_ms=%.1f cold_import_cpu_ms=%.1f "
        + "import_ms=%.1f import_cpu_ms=%.1f write_ms=%.1f rounds=%d%n", first.model().id(), triangles, fitted,
        coldWall, coldCpu, importWall / 1e6, importCpu / 1e6, writeWall / 1e6, rounds);
    out.flush();
    return Main.EXIT_OK;
  }
}
