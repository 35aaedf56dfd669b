package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code robotrun bench window} on a virtual X display (xvfb-run, as {@link WindowLayoutXvfbTest}
 * finds it; skipped outside CI when it is missing, never in CI), one second per phase: it prints the
 * three phase lines in order and then the close line, in the documented format; the jog and the run
 * (the arm moving) drew frames, and the idle window drew at most 5 in its second (it sleeps). A
 * behaviour test: no figure is held to a speed. It runs with {@code ROBOTRUN_REDRAW=check}: every
 * frame the window kept and drew again only where it changed (the still layer, the moving arm, the
 * panels' changed glyphs) is compared with a full redraw, and no frame may differ.
 */
class BenchWindowXvfbTest {
  private static final Pattern PHASE = Pattern.compile(
      "phase=(idle|jog|run) fps=(\\d+\\.\\d) cpu_pct=(\\d+\\.\\d) frame_cpu_ms=(\\d+\\.\\d\\d|-) frames=(\\d+) "
          + "seconds=(\\d+\\.\\d\\d) load=(-?\\d+\\.\\d\\d)");

  @Test
  void idleJogAndRunArePrintedAndTheMovingPhasesDrawFrames(@TempDir Path tmp) throws Exception {
    WindowLayoutXvfbTest.needsXvfb();
    List<String> cmd = new ArrayList<>(List.of("xvfb-run", "-a", "-s", "-screen 0 1366x768x24",
        Path.of(System.getProperty("java.home"), "bin", "java").toString(), "--enable-native-access=ALL-UNNAMED",
        "-cp", System.getProperty("java.class.path"), Main.class.getName(),
        "bench", "window", "--seconds", "1", "--scenario", Path.of("scenarios/pick-and-place.json").toAbsolutePath().toString()));
    Path out = tmp.resolve("out.txt");
    Path err = tmp.resolve("err.txt");
    ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile());
    pb.environment().put("ROBOTRUN_REDRAW", "check");
    Process p = pb.start();
    if (!p.waitFor(180, TimeUnit.SECONDS)) {
      p.destroyForcibly();
      throw new AssertionError("bench window did not finish in 180 s: " + Files.readString(err));
    }
    String log = Files.readString(out) + Files.readString(err);
    assertThat(p.exitValue()).as(log).isZero();
    List<String> lines = Files.readAllLines(out).stream().filter(l -> !l.isBlank()).toList();
    assertThat(lines).as(log).hasSize(4);
    String[] names = {"idle", "jog", "run"};
    long[] frames = new long[3];
    for (int i = 0; i < 3; i++) {
      Matcher m = PHASE.matcher(lines.get(i));
      assertThat(m.matches()).as("line %d: %s", i + 1, lines.get(i)).isTrue();
      assertThat(m.group(1)).isEqualTo(names[i]);
      frames[i] = Long.parseLong(m.group(5));
      // no frame, no per-frame figure
      assertThat(m.group(4).equals("-")).as(lines.get(i)).isEqualTo(frames[i] == 0);
      // the timer's wake-ups are late by what the machine's load says: only that time was timed
      assertThat(Double.parseDouble(m.group(6))).as("timed seconds").isPositive();
    }
    assertThat(frames[1]).as("frames while jogging").isPositive();
    assertThat(frames[2]).as("frames while running a program").isPositive();
    // An idle window sleeps: it draws only what changes (a few frames a second at most), where one that
    // did not would draw about 60. Compared with a bound, not with the jog's count: a loaded machine
    // starves the jog phase (1 frame at load 44) but can only lower the idle count.
    assertThat(frames[0]).as("an idle window sleeps: frames drawn in its idle second").isLessThanOrEqualTo(5);
    assertThat(lines.get(3)).matches("close_ms=\\d+");
    Matcher check = Pattern.compile("redraw check: (\\d+) frames, at most (\\d+) pixels differed").matcher(Files.readString(err));
    assertThat(check.find()).as(log).isTrue();
    assertThat(Long.parseLong(check.group(1))).as("frames checked").isGreaterThanOrEqualTo(frames[0] + frames[1] + frames[2]);
    assertThat(Long.parseLong(check.group(2))).as("pixels of a kept frame that differ from a full redraw: " + log).isZero();
  }
}
