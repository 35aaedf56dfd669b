package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 18: natives go to a per-content folder made whole under a temporary name and renamed
 * into place, so processes starting together never rewrite a library another has mapped.
 */
class NativeLibrariesTest {
  @TempDir Path dir;

  private static final String PLATFORM = Natives.currentPlatform();

  @Test
  @EnabledOnOs(value = OS.LINUX, architectures = "amd64")
  void findsLwjglAndImguiLibrariesInTheClassPath() throws Exception {
    List<NativeLibraries.Library> libs = NativeLibraries.find(PLATFORM, getClass().getClassLoader());
    assertThat(libs).extracting(NativeLibraries.Library::fileName)
        .contains("liblwjgl.so", "libglfw.so", "liblwjgl_opengl.so", "liblwjgl_stb.so", "libimgui-java64.so");
    assertThat(libs).allMatch(l -> l.size() > 0);
    // The same content, the same folder name; a different CRC, another.
    String h = NativeLibraries.contentHash(libs);
    assertThat(NativeLibraries.contentHash(libs)).isEqualTo(h);
    List<NativeLibraries.Library> changed = new ArrayList<>(libs);
    NativeLibraries.Library first = changed.getFirst();
    changed.set(0, new NativeLibraries.Library(first.fileName(), first.size(), first.crc() ^ 1, first.source()));
    assertThat(NativeLibraries.contentHash(changed)).isNotEqualTo(h);
  }

  @Test
  @EnabledOnOs(value = OS.LINUX, architectures = "amd64")
  void manyInstallingAtOnceAllGetTheSameWholeFolderAndNothingIsRewritten() throws Exception {
    Path root = dir.resolve("natives");
    int n = 8;
    CyclicBarrier start = new CyclicBarrier(n);
    ExecutorService pool = Executors.newFixedThreadPool(n);
    List<Future<Optional<Path>>> results = new ArrayList<>();
    try {
      for (int i = 0; i < n; i++) {
        results.add(pool.submit(() -> {
          start.await();
          return NativeLibraries.install(root, PLATFORM, getClass().getClassLoader());
        }));
      }
      List<Path> got = new ArrayList<>();
      for (Future<Optional<Path>> f : results) {
        got.add(f.get().orElseThrow());
      }
      assertThat(got).containsOnly(got.getFirst());
    } finally {
      pool.shutdown();
    }
    Path folder;
    try (Stream<Path> s = Files.list(root)) {
      List<Path> left = s.toList();
      assertThat(left).as("no partial folder is left").hasSize(1);
      folder = left.getFirst();
    }
    assertThat(folder.getFileName().toString()).startsWith(PLATFORM + "-");
    for (NativeLibraries.Library l : NativeLibraries.find(PLATFORM, getClass().getClassLoader())) {
      Path f = folder.resolve(l.fileName());
      assertThat(Files.size(f)).isEqualTo(l.size());
      java.util.zip.CRC32 crc = new java.util.zip.CRC32();
      crc.update(Files.readAllBytes(f));
      assertThat(crc.getValue()).as(l.fileName()).isEqualTo(l.crc());
    }
    // Later starts find the folder and write nothing.
    var before = Files.getLastModifiedTime(folder.resolve("liblwjgl.so"));
    Thread.sleep(20);
    assertThat(NativeLibraries.install(root, PLATFORM, getClass().getClassLoader())).contains(folder);
    assertThat(Files.getLastModifiedTime(folder.resolve("liblwjgl.so"))).isEqualTo(before);
  }

  @Test
  @EnabledOnOs(value = OS.LINUX, architectures = "amd64")
  void twoRendersStartingAtOnceBothDrawAndShareOneFolder() throws Exception {
    // Two processes racing for a fresh cache: both must finish, with one whole folder between them.
    String javaBin = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    List<Process> ps = new ArrayList<>();
    for (int i = 0; i < 2; i++) {
      ProcessBuilder pb = new ProcessBuilder(javaBin, "--enable-native-access=ALL-UNNAMED", "-cp",
          System.getProperty("java.class.path"), Main.class.getName(), "render", "--out",
          dir.resolve("shot" + i + ".png").toString(), "--width", "160", "--height", "120")
          .redirectErrorStream(true).redirectOutput(dir.resolve("log" + i).toFile());
      pb.environment().put("ROBOTRUN_CACHE_DIR", dir.resolve("cache").toString());
      ps.add(pb.start());
    }
    for (int i = 0; i < 2; i++) {
      assertThat(ps.get(i).waitFor(120, java.util.concurrent.TimeUnit.SECONDS)).isTrue();
      assertThat(ps.get(i).exitValue()).as(Files.readString(dir.resolve("log" + i))).isZero();
      assertThat(Files.size(dir.resolve("shot" + i + ".png"))).isPositive();
    }
    try (Stream<Path> s = Files.list(dir.resolve("cache/natives"))) {
      assertThat(s.map(p -> p.getFileName().toString()).toList()).singleElement()
          .satisfies(n -> assertThat(n).startsWith(PLATFORM + "-"));
    }
  }

  @Test
  void noNativesForThePlatformMeansNothingIsDone() throws Exception {
    assertThat(NativeLibraries.install(dir, "plan9-mips", getClass().getClassLoader())).isEmpty();
    try (Stream<Path> s = Files.list(dir)) {
      assertThat(s.toList()).isEmpty();
    }
  }

  @Test
  void theCacheFolderFollowsEachSystemsConvention() {
    assertThat(NativeLibraries.cacheRoot(Map.of(), "Linux", "/home/s")).contains(Path.of("/home/s/.cache/robotrun"));
    assertThat(NativeLibraries.cacheRoot(Map.of("XDG_CACHE_HOME", "/c"), "Linux", "/home/s")).contains(Path.of("/c/robotrun"));
    assertThat(NativeLibraries.cacheRoot(Map.of("XDG_CACHE_HOME", "rel"), "Linux", "/home/s"))
        .contains(Path.of("/home/s/.cache/robotrun"));
    assertThat(NativeLibraries.cacheRoot(Map.of(), "Mac OS X", "/Users/s"))
        .contains(Path.of("/Users/s/Library/Caches/RobotRun"));
    assertThat(NativeLibraries.cacheRoot(Map.of("LOCALAPPDATA", "/appdata"), "Windows 11", "/u"))
        .contains(Path.of("/appdata", "RobotRun", "cache"));
    assertThat(NativeLibraries.cacheRoot(Map.of(), "Windows 11", "/u")).isEmpty();
    assertThat(NativeLibraries.cacheRoot(Map.of("ROBOTRUN_CACHE_DIR", "/x"), "Linux", "/home/s")).contains(Path.of("/x"));
  }
}
