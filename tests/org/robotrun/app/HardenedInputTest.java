package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.RandomAccessFile;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Hostile inputs on the command line (issue 18): devices, pipes, huge sparse files, bad output
 * paths, absurd limits, control characters. Each is one clear message and exit code 2, found
 * before any simulation runs; never a stack trace, an internal error or a hang.
 */
class HardenedInputTest {
  private record Run(int exit, String out, String err) {}

  private static Run run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    PrintStream oldOut = System.out;
    ByteArrayOutputStream sysOut = new ByteArrayOutputStream();
    System.setOut(new PrintStream(sysOut, true, StandardCharsets.UTF_8));
    try {
      int exit = cl.execute(args);
      return new Run(exit, out + sysOut.toString(StandardCharsets.UTF_8), err.toString());
    } finally {
      System.setOut(oldOut);
    }
  }

  private static final String LOOP = """
      /PROG  LOOP
      /ATTR
      /MN
         1:  LBL[1] ;
         2:  WAIT 1.00(sec) ;
         3:  JMP LBL[1] ;
      /POS
      /END
      """;

  private static Path fifo(Path dir) throws Exception {
    Path f = dir.resolve("pipe.LS");
    Process p = new ProcessBuilder("mkfifo", f.toString()).start();
    assertThat(p.waitFor()).isZero();
    return f;
  }

  @Test
  @EnabledOnOs({OS.LINUX, OS.MAC})
  void aFifoIsNamedAndNeverBlocks(@TempDir Path dir) throws Exception {
    Path f = fifo(dir);
    Run check = run("check", f.toString());
    assertThat(check.exit()).isEqualTo(2);
    assertThat(check.err()).isEqualTo(f + ": cannot read: a named pipe (FIFO), not a regular file\n");
    Run keys = run("pendant", "--keys", f.toString());
    assertThat(keys.exit()).isEqualTo(2);
    assertThat(keys.err()).contains("--keys: cannot read " + f + ": a named pipe (FIFO)");
    Run programs = run("run", "--program", "X", "--programs", f.toString());
    assertThat(programs.exit()).isEqualTo(2);
    assertThat(programs.err()).contains("--programs: cannot read " + f + ": a named pipe (FIFO)");
    Run scenario = run("run", "--scenario", f.toString(), "--program", "X");
    assertThat(scenario.exit()).isEqualTo(2);
    assertThat(scenario.err()).contains("a named pipe (FIFO), not a regular file").doesNotContain("does not exist");
  }

  @Test
  @EnabledOnOs(OS.LINUX)
  void devicesAreRefusedByTheirKind() {
    Run check = run("check", "/dev/zero");
    assertThat(check.exit()).isEqualTo(2);
    assertThat(check.err()).isEqualTo("/dev/zero: cannot read: a character device, not a regular file\n");
    Run scenario = run("run", "--scenario", "/dev/zero", "--program", "X");
    assertThat(scenario.exit()).isEqualTo(2);
    assertThat(scenario.err()).contains("/dev/zero: a character device, not a regular file");
  }

  @Test
  void aHugeSparseProgramIsRefusedWithoutReadingIt(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("BIG.LS");
    try (RandomAccessFile raf = new RandomAccessFile(f.toFile(), "rw")) {
      raf.setLength(3L << 30);
    }
    Run check = run("check", f.toString());
    assertThat(check.exit()).isEqualTo(2);
    assertThat(check.err()).isEqualTo(f + ": cannot read: file is 3072.0 MiB; .LS programs are limited to 16 MiB\n");
  }

  @Test
  @EnabledOnOs(OS.LINUX)
  void unusableOutputsAreFoundBeforeTheRun(@TempDir Path dir) throws Exception {
    Path prog = Files.writeString(dir.resolve("LOOP.LS"), LOOP);
    Path oldTrace = Files.writeString(dir.resolve("old.csv"), "the old trace\n");
    // The loop would run 600 s of simulated time; each refusal must come before it starts.
    Run full = run("run", "--program", "LOOP", "--programs", prog.toString(), "--report", "/dev/full",
        "--trace", oldTrace.toString());
    assertThat(full.exit()).isEqualTo(2);
    assertThat(full.err()).isEqualTo("robotrun: --report: cannot write /dev/full: is a character device, not a regular file\n");
    assertThat(Files.readString(oldTrace)).isEqualTo("the old trace\n");
    Run proc = run("run", "--program", "LOOP", "--programs", prog.toString(), "--trace", "/proc/version");
    assertThat(proc.exit()).isEqualTo(2);
    assertThat(proc.err()).startsWith("robotrun: --trace: cannot write /proc/version: cannot create a file in /proc");
    Run noDir = run("run", "--program", "LOOP", "--programs", prog.toString(), "--report", dir.resolve("no/r.json").toString());
    assertThat(noDir.exit()).isEqualTo(2);
    assertThat(noDir.err()).contains("the folder does not exist");
    Run same = run("run", "--program", "LOOP", "--programs", prog.toString(), "--report", oldTrace.toString(),
        "--trace", oldTrace.toString());
    assertThat(same.exit()).isEqualTo(2);
    assertThat(same.err()).contains("name the same file");
  }

  @Test
  void unreadableProgramFilesAreBadInputNotInternalErrors(@TempDir Path dir) throws Exception {
    Path folder = Files.createDirectories(dir.resolve("sub.LS"));
    Files.writeString(folder.resolve("X.LS"), LOOP);
    Run r = run("run", "--program", "X", "--programs", dir.resolve("nothing.LS").toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains("no such file").doesNotContain("internal error");
  }

  @Test
  void absurdLimitsAreRefusedWithTheirRange(@TempDir Path dir) throws Exception {
    Path prog = Files.writeString(dir.resolve("LOOP.LS"), LOOP);
    Run sim = run("run", "--program", "LOOP", "--programs", prog.toString(), "--max-sim-seconds", "1e308");
    assertThat(sim.exit()).isEqualTo(2);
    assertThat(sim.err()).contains("--max-sim-seconds: expected more than 0 and at most 86400 seconds");
    Run wall = run("run", "--program", "LOOP", "--programs", prog.toString(), "--max-wall-seconds", "0");
    assertThat(wall.exit()).isEqualTo(2);
    assertThat(wall.err()).contains("--max-wall-seconds: expected 1..86400 seconds, got 0");
    Run keys = run("pendant", "--keys", prog.toString(), "--max-wall-seconds", "1e9");
    assertThat(keys.exit()).isEqualTo(2);
    assertThat(keys.err()).contains("--max-wall-seconds: expected 1..86400");
  }

  @Test
  void aKeyScriptThatIsNotUtf8NamesItsLine(@TempDir Path dir) throws Exception {
    Path keys = dir.resolve("k.keys");
    Files.write(keys, new byte[] {'S', 'H', 'O', 'W', '\n', 'T', 'Y', 'P', 'E', ' ', (byte) 0xE9, '\n'});
    Run r = run("pendant", "--keys", keys.toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).startsWith("robotrun: --keys: " + keys + ":2: not UTF-8 text (byte 0xE9");
  }

  @Test
  void keyScriptNumbersFollowTheDecimalGrammar(@TempDir Path dir) throws Exception {
    // issue 26: a plain decimal, as docs/pendant.md says (1e3 was taken as 1000)
    for (String n : new String[] {"0x1p3", "1d", "NaN", "Infinity", "1e999", "1e3", "+2", "2.5e0", "\u0663"}) {
      Path keys = Files.writeString(dir.resolve("k.keys"), "WAIT " + n + "\n");
      Run r = run("pendant", "--keys", keys.toString());
      assertThat(r.exit()).as(n).isEqualTo(2);
      assertThat(r.err()).as(n).contains(":1: WAIT needs seconds");
    }
    Path total = Files.writeString(dir.resolve("t.keys"), "WAIT 3600\n".repeat(4) + "WAIT 1\n");
    Run r = run("pendant", "--keys", total.toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains(":5: the WAITs up to here add up to more than 14400 s");
  }

  @Test
  void typeFollowedBySpacesIsAScriptErrorAndNeverCrashesThePrScreen(@TempDir Path dir) throws Exception {
    Path keys = Files.writeString(dir.resolve("k.keys"), "DATA\nF1\nTYPE    \n");
    Run r = run("pendant", "--keys", keys.toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).isEqualTo("robotrun: " + keys + ":3: TYPE needs the text to type\n");
  }

  @Test
  void controlCharactersAndHugeNamesAreEscapedAndShortened(@TempDir Path dir) {
    String name = "X\u001b[2J" + "A".repeat(5000) + ".LS";
    Run r = run("check", dir.resolve(name).toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).doesNotContain("\u001b").contains("\\e[2J").contains("…").hasSizeLessThan(400);
  }

  @Test
  void reportsDoNotFollowTheMachineLocale(@TempDir Path dir) throws Exception {
    Path prog = Files.writeString(dir.resolve("LOOP.LS"), LOOP);
    Locale before = Locale.getDefault();
    Locale.setDefault(Locale.GERMANY);
    try {
      Path report = dir.resolve("r.json");
      Run r = run("run", "--program", "LOOP", "--programs", prog.toString(), "--max-sim-seconds", "2",
          "--report", report.toString());
      assertThat(r.exit()).isEqualTo(1);
      JsonNode j = new ObjectMapper().readTree(report.toFile());
      assertThat(j.get("alarm").get("message").asText()).contains("ran 2.0 s").doesNotContain("2,0");
      assertThat(r.out()).contains("2.0 s");
    } finally {
      Locale.setDefault(before);
    }
  }

  @Test
  void aRegisterOverflowIsAnAlarmAndTheReportHoldsOnlyNumbers(@TempDir Path dir) throws Exception {
    Path prog = Files.writeString(dir.resolve("GROW.LS"), """
        /PROG  GROW
        /ATTR
        /MN
           1:  R[1]=10 ;
           2:  LBL[1] ;
           3:  R[1]=R[1]*R[1] ;
           4:  JMP LBL[1] ;
        /POS
        /END
        """);
    Path report = dir.resolve("r.json");
    Run r = run("run", "--program", "GROW", "--programs", prog.toString(), "--report", report.toString());
    assertThat(r.exit()).isEqualTo(1);
    String json = Files.readString(report);
    assertThat(json).doesNotContain("NaN").doesNotContain("Infinity");
    JsonNode j = new ObjectMapper().readTree(json);
    assertThat(j.get("alarm").get("code").asText()).isEqualTo("INTP-304");
    assertThat(j.get("alarm").get("message").asText()).contains("value overflow");
    assertThat(j.get("alarm").get("line").asInt()).isEqualTo(3);
    assertThat(j.get("robots").get(0).get("registers").get("R").get("1").isNumber()).isTrue();
  }

  @Test
  void aTraceIsWrittenWholeWithNoTemporaryFileLeft(@TempDir Path dir) throws Exception {
    Path prog = Files.writeString(dir.resolve("LOOP.LS"), LOOP);
    Path trace = Files.writeString(dir.resolve("t.csv"), "old\n");
    Run r = run("run", "--program", "LOOP", "--programs", prog.toString(), "--max-sim-seconds", "1",
        "--trace", trace.toString());
    assertThat(r.exit()).isEqualTo(1);
    assertThat(Files.readAllLines(trace)).hasSize(252).doesNotContain("old");
    try (Stream<Path> s = Files.list(dir)) {
      assertThat(s.map(p -> p.getFileName().toString())).containsExactlyInAnyOrder("LOOP.LS", "t.csv");
    }
  }

  /** Issue 26: a '%' in a help text (Windows' %APPDATA%) made picocli warn before every gui --help. */
  @Test
  void everyHelpTextFormatsWithoutAWarning() {
    java.util.List<CommandLine> all = new java.util.ArrayList<>(java.util.List.of(Main.commandLine()));
    for (int i = 0; i < all.size(); i++) {
      all.addAll(all.get(i).getSubcommands().values());
    }
    PrintStream oldErr = System.err;
    ByteArrayOutputStream sysErr = new ByteArrayOutputStream();
    System.setErr(new PrintStream(sysErr, true, StandardCharsets.UTF_8));
    try {
      for (CommandLine c : all) {
        String help = c.getUsageMessage();
        assertThat(help).as(c.getCommandSpec().qualifiedName()).doesNotContain("%n");
      }
    } finally {
      System.setErr(oldErr);
    }
    assertThat(sysErr.toString(StandardCharsets.UTF_8)).isEmpty();
    assertThat(all).hasSizeGreaterThan(10);
    assertThat(Main.commandLine().getSubcommands().get("gui").getUsageMessage()).contains("Windows %APPDATA%")
        .doesNotContain("%%");
  }

  @Test
  @EnabledOnOs({OS.LINUX, OS.MAC})
  void checkAsJsonCarriesTheFilesItCouldNotRead(@TempDir Path dir) throws Exception {
    Path f = fifo(dir);
    Path loop = dir.resolve("LOOP.LS");
    Files.createSymbolicLink(loop, loop);
    for (Path p : new Path[] {f, loop, Path.of("/dev/zero")}) {
      // through run(), which captures System.out as well: picocli used to send the JSON to the old System.out
      Run r = run("check", "--format", "json", p.toString());
      assertThat(r.exit()).as(p.toString()).isEqualTo(2);
      assertThat(r.err()).startsWith(p + ": cannot read: ");
      JsonNode json = new ObjectMapper().readTree(r.out());
      assertThat(json.get("errors").asInt()).as(p.toString()).isEqualTo(1);
      assertThat(json.get("diagnostics").get(0).get("file").asText()).isEqualTo(p.toString());
      assertThat(json.get("diagnostics").get(0).get("message").asText()).startsWith("cannot read: ");
    }
  }

  /**
   * The root cause of the JSON that went missing: picocli's default execution strategy remembers
   * System.out from when the CommandLine was made and, when System.out has changed since, puts a
   * writer on the old stream in place of the one given to setOut. Output must go to setOut's writer.
   */
  @Test
  void outputGoesToTheWriterGivenEvenWhenSystemOutChangedAfterTheCommandLineWasMade() {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(new StringWriter()));
    PrintStream oldOut = System.out;
    ByteArrayOutputStream sysOut = new ByteArrayOutputStream();
    System.setOut(new PrintStream(sysOut, true, StandardCharsets.UTF_8));
    int exit;
    try {
      exit = cl.execute("check", "--format", "json", "scenarios/programs/PICKPLACE.LS");
    } finally {
      System.setOut(oldOut);
    }
    assertThat(exit).isZero();
    assertThat(out.toString()).startsWith("{\"diagnostics\":").contains("\"errors\":0");
    assertThat(sysOut.toString(StandardCharsets.UTF_8)).isEmpty();
  }

  @Test
  void aTaskWhoseScenarioIsADeviceSaysSo(@TempDir Path dir) throws Exception {
    Path task = Files.writeString(dir.resolve("t.task.json"), "{\"format\": 1, \"scenario\": \"/dev/zero\", \"checks\": []}");
    Run r = run("grade", "--task", task.toString(), dir.toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains("scenario: cannot read the scenario /dev/zero: a character device, not a regular file")
        .doesNotContain("not found");
  }

  @Test
  void seedOptionsTakeWhatVisionSeedTakes() {
    for (String[] cmd : new String[][] {{"run", "--scenario", "scenarios/vision-pick.json", "--seed", "9223372036854775807"},
        {"render", "--scenario", "scenarios/vision-pick.json", "--seed", "-9000000000000000", "--out", "x.png"}}) {
      Run r = run(cmd);
      assertThat(r.exit()).isEqualTo(2);
      assertThat(r.err()).contains("--seed: expected a whole number from -8999999999999999 to 8999999999999999 (as vision.seed)");
    }
  }

  /**
   * Issue 26, "more of the same kind": a scenario file that is empty, UTF-16, has a NUL, NaN,
   * Infinity, a number of 400 digits, a 5 MB line, nesting 5000 deep, or is a folder: every command
   * that reads a scenario answers with one line naming the file, exit 2, no trace.
   */
  @Test
  void hostileScenarioFilesAreOneClearLineForEveryCommand(@TempDir Path dir) throws Exception {
    String good = Files.readString(Path.of("scenarios/empty-cell.json"));
    java.util.Map<String, byte[]> files = new java.util.LinkedHashMap<>();
    files.put("empty.json", new byte[0]);
    files.put("utf16.json", good.getBytes(StandardCharsets.UTF_16));
    files.put("nul.json", (good.substring(0, 20) + "\u0000" + good.substring(20)).getBytes(StandardCharsets.UTF_8));
    files.put("nan.json", good.replaceFirst("\"x\": 0", "\"x\": NaN").getBytes(StandardCharsets.UTF_8));
    files.put("inf.json", good.replaceFirst("\"x\": 0", "\"x\": -Infinity").getBytes(StandardCharsets.UTF_8));
    files.put("big.json", good.replaceFirst("\"x\": 0", "\"x\": 1" + "0".repeat(400)).getBytes(StandardCharsets.UTF_8));
    files.put("long.json", ("{\"format\": 1, \"name\": \"" + "a".repeat(5_000_000) + "\"}").getBytes(StandardCharsets.UTF_8));
    files.put("deep.json", ("{\"format\": 1, \"robots\": " + "[".repeat(5000) + "]".repeat(5000) + "}").getBytes(StandardCharsets.UTF_8));
    for (var e : files.entrySet()) {
      Files.write(dir.resolve(e.getKey()), e.getValue());
    }
    Files.createDirectory(dir.resolve("folder.json"));
    java.util.List<String> names = new java.util.ArrayList<>(files.keySet());
    names.add("folder.json");
    for (String n : names) {
      String f = dir.resolve(n).toString();
      for (String[] args : new String[][] {{"run", "--scenario", f, "--max-sim-seconds", "1"},
          {"render", "--scenario", f, "--out", dir.resolve("x.png").toString()},
          {"pendant", "--scenario", f, "--keys", f}}) {
        Run r = run(args);
        assertThat(r.exit()).as(n + " " + args[0] + ": " + r.err()).isEqualTo(2);
        assertThat(r.err()).as(n + " " + args[0]).contains(n).doesNotContain("Exception").doesNotContain("internal error")
            .doesNotContain("\tat ");
      }
    }
  }
}
