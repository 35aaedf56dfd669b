package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 26: the run report says the state at the end (UOP outputs of the last robot) and what each part became. */
class ReportEndStateTest {
  private static JsonNode report(Path dir, String... args) throws Exception {
    Path out = dir.resolve("r.json");
    var cl = Main.commandLine();
    StringWriter o = new StringWriter();
    StringWriter e = new StringWriter();
    cl.setOut(new PrintWriter(o));
    cl.setErr(new PrintWriter(e));
    String[] all = new String[args.length + 3];
    all[0] = "run";
    System.arraycopy(args, 0, all, 1, args.length);
    all[args.length + 1] = "--report";
    all[args.length + 2] = out.toString();
    assertThat(cl.execute(all)).as(e.toString()).isZero();
    return new ObjectMapper().readTree(out.toFile());
  }

  @Test
  void progrunAndBusyAreOffForEveryRobotOnceItsProgramEnded(@TempDir Path dir) throws Exception {
    JsonNode r = report(dir, "--scenario", "scenarios/two-robot-handshake.json");
    assertThat(r.get("robots")).hasSize(2);
    for (JsonNode robot : r.get("robots")) {
      JsonNode uo = robot.path("io").path("UO");
      assertThat(uo.path("3").asBoolean(false)).as(robot.get("name") + " PROGRUN").isFalse();
      assertThat(uo.path("10").asBoolean(false)).as(robot.get("name") + " BUSY").isFalse();
    }
  }

  @Test
  void everyPartSaysItsShapeColourAndVisionModels(@TempDir Path dir) throws Exception {
    JsonNode r = report(dir, "--scenario", "scenarios/vision-pick.json");
    assertThat(r.get("parts")).isNotEmpty();
    for (JsonNode p : r.get("parts")) {
      assertThat(p.get("shape").asText()).isIn("box", "cylinder", "mesh");
      assertThat(p.get("colour").asText()).matches("#[0-9a-f]{6}");
      assertThat(p.get("models")).as(p.get("name").asText()).isNotEmpty();
    }
    JsonNode plain = report(dir, "--scenario", "scenarios/pick-and-place.json");
    assertThat(plain.get("parts").get(0).get("models")).isEmpty();
  }
}
