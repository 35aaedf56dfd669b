package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code robotrun run}: exit codes, report and trace. */
class RunCommandTest {
  static final Path EXAMPLE = Path.of("resources/examples/PICKPLACE.LS");

  @Test
  void exampleProgramFinishesWithAReportAndATrace(@TempDir Path dir) throws Exception {
    Path report = dir.resolve("r.json");
    Path trace = dir.resolve("t.csv");
    int code = Main.execute("run", "--program", "PICKPLACE", "--programs", EXAMPLE.toString(),
        "--report", report.toString(), "--trace", trace.toString());
    assertThat(code).isZero();
    JsonNode r = new ObjectMapper().readTree(report.toFile());
    assertThat(r.get("status").asText()).isEqualTo("finished");
    assertThat(r.get("alarm").isNull()).isTrue();
    JsonNode robot = r.get("robots").get(0);
    assertThat(robot.get("registers").get("R").get("2").asInt()).isEqualTo(4);
    assertThat(robot.get("joints_deg").get(4).asDouble()).isEqualTo(-90.0);
    assertThat(robot.get("tcp_world").get("z").asDouble()).isEqualTo(185.0);
    assertThat(r.get("parts").isArray()).isTrue();
    // One row per tick plus the header and the row at time 0.
    long rows = Files.readAllLines(trace).size();
    assertThat(rows).isEqualTo(Math.round(r.get("simTimeSec").asDouble() / 0.004) + 2);
  }

  @Test
  void scenarioSuppliesTheCellFramesAndParts(@TempDir Path dir) throws Exception {
    Path prog = dir.resolve("ABOVE.LS");
    Files.writeString(prog, """
        /PROG  ABOVE
        /ATTR
        /MN
           1:  UFRAME_NUM=1 ;
           2:  UTOOL_NUM=1 ;
           3:L P[1:ABOVE_PART1] 200mm/sec FINE ;
        /POS
        P[1:"ABOVE_PART1"]{
           GP1:
        	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
        	X =   120.000  mm,	Y =   170.000  mm,	Z =   100.000  mm,
        	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
        };
        /END
        """);
    Path report = dir.resolve("r.json");
    int code = Main.execute("run", "--scenario", "scenarios/pick-and-place.json", "--program", "ABOVE",
        "--programs", prog.toString(), "--report", report.toString());
    assertThat(code).isZero();
    JsonNode r = new ObjectMapper().readTree(report.toFile());
    JsonNode tcp = r.get("robots").get(0).get("tcp_world");
    // UFRAME[1] is the table corner at (220, -350, -100): the TCP ends 100 mm above part1's base.
    assertThat(tcp.get("x").asDouble()).isEqualTo(340.0);
    assertThat(tcp.get("y").asDouble()).isEqualTo(-180.0);
    assertThat(tcp.get("z").asDouble()).isEqualTo(0.0);
    assertThat(r.get("parts")).hasSize(3);
    assertThat(r.get("parts").get(0).get("name").asText()).isEqualTo("part1");
    assertThat(r.get("parts").get(0).get("heldBy").isNull()).isTrue();
  }

  @Test
  void drivingTheToolIntoTheTableIsACollisionAlarm(@TempDir Path dir) throws Exception {
    Path prog = dir.resolve("CRASH.LS");
    Files.writeString(prog, """
        /PROG  CRASH
        /ATTR
        /MN
           1:  UFRAME_NUM=1 ;
           2:  UTOOL_NUM=1 ;
           3:L P[1:ABOVE] 200mm/sec FINE ;
           4:L P[2:INTO] 100mm/sec FINE ;
        /POS
        P[1:"ABOVE"]{
           GP1:
        	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
        	X =   120.000  mm,	Y =   370.000  mm,	Z =    50.000  mm,
        	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
        };
        P[2:"INTO"]{
           GP1:
        	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
        	X =   120.000  mm,	Y =   370.000  mm,	Z =   -20.000  mm,
        	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
        };
        /END
        """);
    Path report = dir.resolve("r.json");
    int code = Main.execute("run", "--scenario", "scenarios/pick-and-place.json", "--program", "CRASH",
        "--programs", prog.toString(), "--report", report.toString());
    assertThat(code).isEqualTo(1);
    JsonNode r = new ObjectMapper().readTree(report.toFile());
    assertThat(r.get("alarm").get("code").asText()).isEqualTo("SRVO-050");
    assertThat(r.get("alarm").get("line").asInt()).isEqualTo(4);
    JsonNode hit = r.get("collisions").get(0);
    // The gripper's finger tips are the TCP: a finger meets the table first.
    assertThat(java.util.List.of(hit.get("a").asText(), hit.get("b").asText()))
        .containsExactlyInAnyOrder("robot1/tool/finger1", "table");
    // the student's names beside the ids, and in the alarm text
    assertThat(java.util.List.of(hit.get("aName").asText(), hit.get("bName").asText()))
        .containsExactlyInAnyOrder("robot1 gripper finger1", "table");
    assertThat(r.get("alarm").get("message").asText()).contains("robot1 gripper finger1").doesNotContain("/");
    // The tip stopped at the table top (z = -100 in the cell), not inside it: at most one tick deeper.
    assertThat(r.get("robots").get(0).get("tcp_world").get("z").asDouble()).isBetween(-100.5, -99.0);
  }

  @Test
  void alarmExitsWithOneAndNamesTheLine(@TempDir Path dir) throws Exception {
    Path prog = dir.resolve("BAD.LS");
    Files.writeString(prog, """
        /PROG  BAD
        /ATTR
        /MN
           1:  R[1]=1 ;
           2:  R[2]=R[1]/0 ;
        /END
        """);
    Path report = dir.resolve("r.json");
    int code = Main.execute("run", "--program", "BAD", "--programs", dir.toString(), "--report", report.toString());
    assertThat(code).isEqualTo(1);
    JsonNode alarm = new ObjectMapper().readTree(report.toFile()).get("alarm");
    assertThat(alarm.get("code").asText()).isEqualTo("SIMU-001");
    assertThat(alarm.get("line").asInt()).isEqualTo(2);
    assertThat(alarm.get("program").asText()).isEqualTo("BAD");
  }

  @Test
  void timeLimitExitsWithOne(@TempDir Path dir) throws Exception {
    Path prog = dir.resolve("LOOP.LS");
    Files.writeString(prog, """
        /PROG  LOOP
        /ATTR
        /MN
           1:  LBL[1] ;
           2:  WAIT 1.00(sec) ;
           3:  JMP LBL[1] ;
        /END
        """);
    assertThat(Main.execute("run", "--program", "LOOP", "--programs", prog.toString(), "--max-sim-seconds", "3")).isEqualTo(1);
  }

  @Test
  void badInputExitsWithTwo(@TempDir Path dir) throws Exception {
    assertThat(Main.execute("run", "--program", "NOPE", "--programs", EXAMPLE.toString())).isEqualTo(2);
    assertThat(Main.execute("run", "--program", "PICKPLACE", "--programs", EXAMPLE.toString(), "--override", "0")).isEqualTo(2);
    assertThat(Main.execute("run", "--program", "PICKPLACE", "--programs", dir.resolve("missing").toString())).isEqualTo(2);
    Path broken = dir.resolve("BROKEN.LS");
    Files.writeString(broken, "/PROG  BROKEN\n/MN\n   1:  R[1]=((1 ;\n/END\n");
    assertThat(Main.execute("run", "--program", "BROKEN", "--programs", broken.toString())).isEqualTo(2);
    assertThat(Main.execute("run", "--programs", EXAMPLE.toString())).isEqualTo(2);
  }

  @Test
  void aProgramNameDefinedByTwoFilesIsBadInputNamingBoth(@TempDir Path dir) throws Exception {
    Files.copy(EXAMPLE, dir.resolve("A.LS"));
    Files.copy(EXAMPLE, dir.resolve("B.ls"));
    assertThatThrownBy(() -> RunCommand.loadPrograms(List.of(dir)))
        .isInstanceOf(UserError.class)
        .hasMessage(dir.resolve("B.ls") + ":1: program PICKPLACE is also defined in " + dir.resolve("A.LS"));
    assertThat(Main.execute("run", "--program", "PICKPLACE", "--programs", dir.toString())).isEqualTo(2);
    // The same file twice is one program.
    assertThat(RunCommand.loadPrograms(List.of(EXAMPLE, EXAMPLE, EXAMPLE.getParent()))).hasSize(1);
  }

  @Test
  void aDirectoryWithoutProgramsIsBadInputSayingSo(@TempDir Path dir) {
    assertThatThrownBy(() -> RunCommand.loadPrograms(List.of(dir)))
        .isInstanceOf(UserError.class)
        .hasMessage("--programs: the directory " + dir + " holds no .LS files");
  }

  @Test
  void theProgramNameMayBeGivenInAnyCase() {
    assertThat(Main.execute("run", "--program", "pickplace", "--programs", EXAMPLE.toString())).isZero();
  }
}
