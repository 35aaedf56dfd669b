package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;

/**
 * Golden programs: every {@code tests/resources/programs/NAME.LS} with a {@code NAME.expect}
 * sidecar (or several: {@code NAME@variant.expect}, e.g. other presets) is read with the .LS
 * reader, run to its end (all programs of the folder are callable;
 * fake motions take 0.1 s; ticks of 4 ms) and its final state compared with the sidecar.
 *
 * <p>Sidecar lines ({@code #} starts a comment): {@code set R[1]=4} / {@code set RI[1]=ON}
 * preset a register or port; {@code outcome=finished|paused|alarm}; {@code alarm=CODE};
 * {@code alarm_line=N}; {@code motions=N} (requests sent to the port); {@code R[i]=14} (an
 * integer) or {@code R[i]=14.0} (a real, ±1e-6); {@code DO[i]=ON}, {@code GO[i]=5};
 * {@code PR[i,j]=x}; {@code TIMER[i]=s}; {@code uframe=n}, {@code utool=n}, {@code override=n};
 * {@code message=text} (on the user screen).
 */
class GoldenProgramsTest {
  static final Path PROGRAMS = Path.of("tests/resources/programs");
  private static final double DT_SEC = 0.004;
  private static final double MOTION_SEC = 0.1;
  private static final int MAX_TICKS = 20_000;
  private static final double TOLERANCE = 1e-6;

  private static final Pattern REGISTER = Pattern.compile("R\\[(\\d+)]=(-?[\\d.]+)");
  private static final Pattern PORT = Pattern.compile("([A-Z]{1,2})\\[(\\d+)]=(ON|OFF|-?\\d+)");
  private static final Pattern PR_ELEMENT = Pattern.compile("PR\\[(\\d+),(\\d)]=(-?[\\d.]+)");
  private static final Pattern TIMER = Pattern.compile("TIMER\\[(\\d+)]=([\\d.]+)");
  private static final Pattern KEY = Pattern.compile("(outcome|alarm|alarm_line|motions|uframe|utool|override|message)=(.*)");

  static Stream<String> goldenNames() throws IOException {
    try (Stream<Path> s = Files.list(PROGRAMS)) {
      List<String> names = s.map(p -> p.getFileName().toString())
          .filter(n -> n.endsWith(".expect"))
          .map(n -> n.substring(0, n.length() - ".expect".length()))
          .sorted().toList();
      assertThat(names).isNotEmpty();
      return names.stream();
    }
  }

  private static List<Program> allPrograms() throws IOException {
    List<Program> programs = new ArrayList<>();
    try (Stream<Path> s = Files.list(PROGRAMS)) {
      for (Path p : s.filter(f -> f.toString().endsWith(".LS")).sorted().toList()) {
        LsReadResult r = LsReader.read(p);
        // An unsupported statement loads (and alarms when it runs, as UNSUPP.LS expects).
        assertThat(r.diagnostics()).as(p.toString()).filteredOn(Diagnostic::isError)
            .filteredOn(d -> d.kind() != Diagnostic.Kind.UNSUPPORTED).isEmpty();
        programs.add(r.program());
      }
    }
    return programs;
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("goldenNames")
  void programEndsInTheExpectedState(String name) throws IOException {
    List<Program> programs = allPrograms();
    String program = name.contains("@") ? name.substring(0, name.indexOf('@')) : name;
    assertThat(programs).extracting(Program::name).as("%s.LS next to %s.expect", program, name).contains(program);
    FakeMotionPort port = new FakeMotionPort(MOTION_SEC);
    Registers regs = new Registers();
    Interpreter interp = new Interpreter(ProgramStore.of(programs), regs, port, InterpreterSettings.defaults());
    List<String> expect = Files.readAllLines(PROGRAMS.resolve(name + ".expect"), StandardCharsets.UTF_8).stream()
        .map(String::strip).filter(l -> !l.isEmpty() && !l.startsWith("#")).toList();

    for (String line : expect) {
      if (line.startsWith("set ")) {
        preset(regs, line.substring(4).strip());
      }
    }
    interp.select(program);
    interp.forward();
    Outcome o = null;
    for (int i = 0; i < MAX_TICKS; i++) {
      port.advance(DT_SEC);
      o = interp.tick(DT_SEC);
      if (o instanceof Outcome.Finished || o instanceof Outcome.Paused || o instanceof Outcome.Alarmed) {
        break;
      }
    }

    boolean sawOutcome = false;
    for (String line : expect) {
      if (line.startsWith("set ")) {
        continue;
      }
      String what = name + ".expect: " + line;
      Matcher m;
      if ((m = KEY.matcher(line)).matches()) {
        String v = m.group(2);
        switch (m.group(1)) {
          case "outcome" -> {
            sawOutcome = true;
            Class<?> type = switch (v) {
              case "finished" -> Outcome.Finished.class;
              case "paused" -> Outcome.Paused.class;
              case "alarm" -> Outcome.Alarmed.class;
              default -> throw new AssertionError(what + ": unknown outcome");
            };
            assertThat(o).as(what).isInstanceOf(type);
          }
          case "alarm" -> assertThat(alarm(o, what).code()).as(what + " (" + alarm(o, what).display() + ")").isEqualTo(v);
          case "alarm_line" -> assertThat(alarm(o, what).line()).as(what + " (" + alarm(o, what).display() + ")")
              .isEqualTo(Integer.parseInt(v));
          case "motions" -> assertThat(port.requests()).as(what).hasSize(Integer.parseInt(v));
          case "uframe" -> assertThat(port.activeFrame(Instruction.FrameKind.USER)).as(what).isEqualTo(Integer.parseInt(v));
          case "utool" -> assertThat(port.activeFrame(Instruction.FrameKind.TOOL)).as(what).isEqualTo(Integer.parseInt(v));
          case "override" -> assertThat(port.overridePct()).as(what).isEqualTo(Integer.parseInt(v));
          case "message" -> assertThat(interp.userScreen()).as(what).contains(v);
          default -> throw new AssertionError(what + ": unknown key");
        }
      } else if ((m = REGISTER.matcher(line)).matches()) {
        int i = Integer.parseInt(m.group(1));
        boolean real = m.group(2).contains(".");
        assertThat(regs.number(i)).as(what).isCloseTo(Double.parseDouble(m.group(2)), within(TOLERANCE));
        assertThat(regs.isInteger(i)).as(what + " (integer vs real)").isEqualTo(!real);
      } else if ((m = PORT.matcher(line)).matches()) {
        IoKind kind = IoKind.valueOf(m.group(1));
        int i = Integer.parseInt(m.group(2));
        int want = switch (m.group(3)) {
          case "ON" -> 1;
          case "OFF" -> 0;
          default -> Integer.parseInt(m.group(3));
        };
        assertThat(regs.value(kind, i)).as(what).isEqualTo(want);
      } else if ((m = PR_ELEMENT.matcher(line)).matches()) {
        Position p = regs.position(Integer.parseInt(m.group(1)));
        assertThat(p.element(Integer.parseInt(m.group(2)))).as(what).isCloseTo(Double.parseDouble(m.group(3)), within(TOLERANCE));
      } else if ((m = TIMER.matcher(line)).matches()) {
        assertThat(regs.timerSec(Integer.parseInt(m.group(1)))).as(what).isCloseTo(Double.parseDouble(m.group(2)), within(TOLERANCE));
      } else {
        throw new AssertionError(what + ": cannot read this line");
      }
    }
    assertThat(sawOutcome).as(name + ".expect names an outcome").isTrue();
  }

  private static Alarm alarm(Outcome o, String what) {
    assertThat(o).as(what).isInstanceOf(Outcome.Alarmed.class);
    return ((Outcome.Alarmed) o).alarm();
  }

  private static void preset(Registers regs, String line) {
    Matcher m;
    if ((m = REGISTER.matcher(line)).matches()) {
      String v = m.group(2);
      if (v.contains(".")) {
        regs.setReal(Integer.parseInt(m.group(1)), Double.parseDouble(v));
      } else {
        regs.setInteger(Integer.parseInt(m.group(1)), Integer.parseInt(v));
      }
    } else if ((m = PORT.matcher(line)).matches()) {
      IoKind kind = IoKind.valueOf(m.group(1));
      String v = m.group(3);
      regs.setValue(kind, Integer.parseInt(m.group(2)), v.equals("ON") ? 1 : v.equals("OFF") ? 0 : Integer.parseInt(v));
    } else {
      throw new AssertionError("set " + line + ": cannot read this preset");
    }
  }

  @Test
  void goldenProgramsWithExpectationsUseEveryStatement() throws IOException {
    Set<String> expected = new HashSet<>(goldenNames().map(n -> n.replaceAll("@.*", "")).toList());
    Set<Class<?>> used = new HashSet<>();
    for (Program p : allPrograms()) {
      if (expected.contains(p.name())) {
        p.lines().forEach(l -> used.add(l.getClass()));
      }
    }
    Set<Class<?>> all = new HashSet<>(List.of(Instruction.class.getPermittedSubclasses()));
    all.removeAll(used);
    assertThat(all).as("statements no golden program uses").isEmpty();
  }
}
