package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The window is the default command: its options and a scenario file work without naming it. */
class MainArgumentsTest {
  @Test
  void windowOptionsWithoutTheCommandGoToTheWindow() {
    assertThat(Main.withDefaultCommand(new String[] {"--scenario", "cell.json"}))
        .containsExactly("gui", "--scenario", "cell.json");
    assertThat(Main.withDefaultCommand(new String[] {"--width=800"})).containsExactly("gui", "--width=800");
  }

  @Test
  void aLoneScenarioFileOpensTheWindowOnIt() {
    assertThat(Main.withDefaultCommand(new String[] {"scenarios/Pick.JSON"}))
        .containsExactly("gui", "--scenario", "scenarios/Pick.JSON");
  }

  @Test
  void aLoneTpProgramOpensTheWindowWithItLoaded() {
    // A file manager opening a .LS file associated with the installed app runs "RobotRun FILE.LS".
    assertThat(Main.withDefaultCommand(new String[] {"/home/s/PICK.LS"}))
        .containsExactly("gui", "--program", "/home/s/PICK.LS");
    assertThat(Main.withDefaultCommand(new String[] {"check", "PICK.LS"})).containsExactly("check", "PICK.LS");
    // RobotRun's own scenario extension, and a hand-in (read-only), as a file manager passes them.
    assertThat(Main.withDefaultCommand(new String[] {"/home/s/Cell 1.RRCELL"}))
        .containsExactly("gui", "--scenario", "/home/s/Cell 1.RRCELL");
    assertThat(Main.withDefaultCommand(new String[] {"hand-in.zip"})).containsExactly("gui", "--workspace", "hand-in.zip");
    assertThat(Main.withDefaultCommand(new String[] {"c.rrcell", "--quit-after-frames", "3"}))
        .containsExactly("gui", "--scenario", "c.rrcell", "--quit-after-frames", "3");
    assertThat(Main.withDefaultCommand(new String[] {"run", "--scenario", "x.rrcell"}))
        .containsExactly("run", "--scenario", "x.rrcell");
  }

  @Test
  void subcommandsHelpAndVersionAreLeftAlone() {
    assertThat(Main.withDefaultCommand(new String[] {})).isEmpty();
    assertThat(Main.withDefaultCommand(new String[] {"--help"})).containsExactly("--help");
    assertThat(Main.withDefaultCommand(new String[] {"-V"})).containsExactly("-V");
    assertThat(Main.withDefaultCommand(new String[] {"run", "--scenario", "x.json"}))
        .containsExactly("run", "--scenario", "x.json");
    assertThat(Main.withDefaultCommand(new String[] {"check", "a.json"})).containsExactly("check", "a.json");
  }

  @Test
  void theFastVersionLineIsWhatPicocliPrints() {
    java.io.StringWriter out = new java.io.StringWriter();
    picocli.CommandLine cl = Main.commandLine();
    cl.setOut(new java.io.PrintWriter(out, true));
    assertThat(cl.execute("--version")).isZero();
    assertThat(out.toString().strip()).isEqualTo(Main.versionLine()).startsWith("robotrun ");
  }

  @Test
  void aBadWindowOptionIsReportedByTheWindowCommand() {
    // Exit 2 with a one-line message, as for any bad option; nothing opens.
    assertThat(Main.execute("--no-such-option")).isEqualTo(Main.EXIT_BAD_INPUT);
  }
}
