package org.robotrun.io;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.robotrun.program.InterpreterSettings;
import org.robotrun.program.Program;
import org.robotrun.world.RobotSetup;

/**
 * A cell's macro table for {@code check --macros}: what an instructor gives so that macro lines
 * ({@code Open hand 1}, {@code HAND1 OPEN}) are checked against the programs they run. Either a
 * scenario (its robots' {@code "macros"}, all robots together) or a text file with one
 * {@code MACRO NAME = PROGRAM} per line ({@code #} starts a remark), as the controller's MACRO
 * setup screen lists it.
 */
public final class MacroTables {
  /** Largest text table read. */
  private static final long MAX_BYTES = 1L << 20;

  private MacroTables() {}

  /**
   * The table, keyed as {@link InterpreterSettings#macroKey} keys macro names.
   *
   * @throws FileFormatException naming the file and line of a bad entry, or the scenario's errors
   * @throws IOException when the file cannot be read
   */
  public static Map<String, String> read(Path file) throws IOException {
    String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
    Map<String, String> out = new LinkedHashMap<>();
    if (name.toLowerCase(Locale.ROOT).endsWith(".json")) {
      switch (ScenarioReader.read(file)) {
        case ScenarioLoad.Loaded l -> {
          for (RobotSetup r : l.scenario().robots()) {
            for (RobotSetup.Macro m : r.macros()) {
              out.putIfAbsent(InterpreterSettings.macroKey(m.name()), m.program().toUpperCase(Locale.ROOT));
            }
          }
        }
        case ScenarioLoad.Failed f -> throw new FileFormatException(file.toString(), f.errors().get(0).line(),
            "not a scenario the macro table can be read from: " + f.message());
      }
      return out;
    }
    String text = BoundedFiles.readUtf8(file, MAX_BYTES, "macro tables");
    String[] lines = text.split("\r?\n", -1);
    for (int i = 0; i < lines.length; i++) {
      String line = lines[i];
      int hash = line.indexOf('#');
      String entry = (hash >= 0 ? line.substring(0, hash) : line).strip();
      if (entry.isEmpty()) {
        continue;
      }
      int eq = entry.lastIndexOf('=');
      String macro = eq < 0 ? "" : entry.substring(0, eq).strip();
      String program = eq < 0 ? "" : entry.substring(eq + 1).strip();
      if (macro.isEmpty() || !Program.isValidName(program)) {
        throw new FileFormatException(file.toString(), i + 1,
            "expected 'MACRO NAME = PROGRAM' (a program name: letters, digits and '_'), found '"
                + TerminalText.safe(entry.length() > 60 ? entry.substring(0, 60) + "..." : entry) + "'");
      }
      if (out.putIfAbsent(InterpreterSettings.macroKey(macro), program.toUpperCase(Locale.ROOT)) != null) {
        throw new FileFormatException(file.toString(), i + 1, "macro '" + TerminalText.safe(macro) + "' is listed twice");
      }
    }
    return out;
  }
}
