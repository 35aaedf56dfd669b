package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** A .LS file opened from the file manager: bad programs are refused before any window opens. */
class GuiProgramOptionTest {
  @TempDir Path dir;

  private int run(StringWriter err, String... args) {
    CommandLine cl = Main.commandLine();
    cl.setErr(new PrintWriter(err, true));
    return cl.execute(Main.withDefaultCommand(args));
  }

  @Test
  void aMissingProgramFileIsBadInputNamingTheFile() {
    StringWriter err = new StringWriter();
    Path missing = dir.resolve("NOPE.LS");
    assertThat(run(err, missing.toString())).isEqualTo(Main.EXIT_BAD_INPUT);
    assertThat(err.toString()).contains("NOPE.LS").containsAnyOf("does not exist", "no such file").doesNotContain("at org.");
  }

  @Test
  void aProgramWithErrorsIsBadInputWithFileAndLine() throws Exception {
    Path bad = dir.resolve("BAD.LS");
    // Not a TP program at all: no /PROG header (a reader error, whatever the statement rules).
    Files.writeString(bad, "MOVE TO THE TRAY\n", StandardCharsets.UTF_8);
    StringWriter err = new StringWriter();
    PrintStream oldErr = System.err;
    ByteArrayOutputStream sysErr = new ByteArrayOutputStream();
    System.setErr(new PrintStream(sysErr, true, StandardCharsets.UTF_8));
    try {
      assertThat(run(err, "gui", "--program", bad.toString())).isEqualTo(Main.EXIT_BAD_INPUT);
    } finally {
      System.setErr(oldErr);
    }
    assertThat(err + sysErr.toString(StandardCharsets.UTF_8)).contains("BAD.LS:1:").doesNotContain("at org.");
  }
}
