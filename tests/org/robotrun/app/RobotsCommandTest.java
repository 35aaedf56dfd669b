package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import picocli.CommandLine;

class RobotsCommandTest {
  @Test
  void listsEveryLibraryModelWithItsSolverChosenFromTheChain() {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    cl.setOut(new PrintWriter(out));
    assertThat(cl.execute("robots")).isZero();
    List<String> lines = out.toString().lines().toList();
    assertThat(lines).hasSize(1 + RobotDefinitions.LIBRARY.size());
    assertThat(lines.get(0).split("\\s+")).containsExactly("id", "reach_mm", "payload", "wrist", "solver", "coupled_j3", "name");
    assertThat(lines.get(1).split("\\s+", 7)).containsExactly("lrmate200id", "716.8", "7", "spherical", "closed-form", "yes", "FANUC LR Mate 200iD");
    assertThat(lines).anySatisfy(l -> assertThat(l.split("\\s+", 7))
        .containsExactly("crx10ial", "1418.0", "10", "offset", "offset-wrist", "yes", "FANUC CRX-10iA/L"));
    assertThat(lines).anySatisfy(l -> assertThat(l.split("\\s+", 7))
        .containsExactly("r2000ic165f", "2686.6", "165", "spherical", "closed-form", "yes", "FANUC R-2000iC/165F"));
  }
}
