package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import net.jqwik.api.lifecycle.AfterContainer;
import net.jqwik.api.lifecycle.BeforeContainer;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInException;
import org.robotrun.io.HandInFiles;

/**
 * Fuzzing the one hand-in reader (issue 26): zips of names a hostile or careless student might
 * put in (traversal, a manifest twice, a file inside a file, control characters, long names,
 * stray folders) with good, binary or empty contents, and byte mutations of a good zip. The
 * grader's loader never throws, keeps no temporary copy of a refused zip and removes the copy of
 * an accepted one; {@code run --workspace}'s unpack refuses exactly what the grader refuses
 * (one rule). Quick property in every build (seed 26); {@link HandInFuzzCampaign} is the long
 * campaign ({@code -Pfuzz}).
 */
class HandInFuzzTest {
  private static Path dir;
  private static byte[] good;

  private static final String PROGRAM = "/PROG  MAIN\n/ATTR\n/MN\n   1:  R[1]=1 ;\n/POS\n/END\n";
  private static final List<String> NAMES = List.of("manifest.json", "cell.json", "programs/MAIN.LS", "programs/MAIN.LS",
      "programs/robot2/P.LS", "programs/MAIN.LS/X.LS", "programs/", "programs/robot2/", "scenarios/Exam_2.json",
      "scenarios/", "../evil.LS", "programs/../../evil.LS", "/etc/passwd", "C:\\x.LS", "programs/a/b/c.LS",
      "programs/\u001b[2J.LS", "programs/" + "L".repeat(300) + ".LS", "notes.txt", "__MACOSX/._cell.json", ".DS_Store",
      "programs/.hidden.LS", "programs/main.ls", "");

  @BeforeContainer
  static void setUp() throws Exception {
    dir = Files.createTempDirectory("handin-fuzz");
    java.util.Map<String, byte[]> files = new java.util.LinkedHashMap<>();
    files.put("cell.json", Files.readAllBytes(Path.of("tests/resources/grade/reference/cell.json")));
    files.put("programs/PICKPLACE.LS", Files.readAllBytes(Path.of("tests/resources/grade/reference/programs/PICKPLACE.LS")));
    good = Files.readAllBytes(HandIns.zip(files, "Ada", dir.resolve("good.zip")));
  }

  @AfterContainer
  static void removeDir() throws Exception {
    try (var s = Files.walk(dir)) {
      s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
    }
  }

  @Provide
  Arbitrary<byte[]> zips() {
    Arbitrary<byte[]> content = Arbitraries.oneOf(Arbitraries.just(PROGRAM.getBytes(StandardCharsets.UTF_8)),
        Arbitraries.just("{\"format\":1,\"student\":\"x\",\"files\":{}}".getBytes(StandardCharsets.UTF_8)),
        Arbitraries.bytes().array(byte[].class).ofMaxSize(64), Arbitraries.just(new byte[0]));
    Arbitrary<Tuple.Tuple2<String, byte[]>> entry = Combinators.combine(Arbitraries.of(NAMES), content).as(Tuple::of);
    Arbitrary<byte[]> built = entry.list().ofMaxSize(8).map(es -> {
      ByteArrayOutputStream out = new ByteArrayOutputStream();
      try (HandIns.DuplicateNameZip z = new HandIns.DuplicateNameZip(out)) {
        for (var e : es) {
          z.put(e.get1(), e.get2());
        }
      } catch (java.io.IOException x) {
        throw new java.io.UncheckedIOException(x);
      }
      return out.toByteArray();
    });
    Arbitrary<Integer> at = Arbitraries.integers().between(0, good.length - 1);
    Arbitrary<byte[]> flipped = Combinators.combine(at, Arbitraries.bytes()).as((n, b) -> {
      byte[] v = good.clone();
      v[n] = b;
      return v;
    });
    Arbitrary<byte[]> cut = at.map(n -> java.util.Arrays.copyOf(good, n));
    return Arbitraries.frequencyOf(Tuple.of(5, built), Tuple.of(2, flipped), Tuple.of(1, cut));
  }

  @Property(seed = "26", tries = 150)
  void everyZipIsGradedOrRefusedTheSameWayEverywhere(@ForAll("zips") byte[] zip) throws Exception {
    check(zip);
  }

  static void check(byte[] bytes) throws Exception {
    Path zip = Files.write(dir.resolve("z.zip"), bytes);
    boolean gradeRefuses;
    boolean valid;
    try (Submission s = new SubmissionLoader().load(zip)) {
      gradeRefuses = s.fatal().isPresent();
      valid = !gradeRefuses && s.handInProblems().isEmpty();
      if (gradeRefuses) {
        assertThat(s.tempDir()).isEmpty();
        assertThat(s.fatal().get()).isNotBlank().doesNotContain("Exception");
      } else {
        assertThat(s.tempDir().orElseThrow()).isDirectory();
      }
      s.tempDir().ifPresent(t -> {
        try (Submission ignored = s) {
          // closed below by try-with-resources as well; closing twice is harmless
        }
        assertThat(t).doesNotExist();
      });
    }
    boolean readerRefuses;
    try {
      HandInFiles.readZip(zip, HandInFiles.Limits.DEFAULT);
      readerRefuses = false;
    } catch (HandInException e) {
      readerRefuses = true;
    }
    assertThat(gradeRefuses).as("grade and the reader agree").isEqualTo(readerRefuses);
    Path into = dir.resolve("into");
    try {
      HandIn.unpack(zip, into);
      assertThat(valid).as("run --workspace takes only what grade finds a valid hand-in").isTrue();
    } catch (HandInException e) {
      assertThat(valid).as("run --workspace refuses only what grade does not find valid: " + e.getMessage()).isFalse();
      assertThat(e.getMessage()).startsWith(zip.toString() + ": ");
    }
    try (var s = Files.exists(into) ? Files.walk(into) : java.util.stream.Stream.<Path>empty()) {
      s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
    }
    assertThat(dir.resolve("evil.LS")).doesNotExist();
  }
}
