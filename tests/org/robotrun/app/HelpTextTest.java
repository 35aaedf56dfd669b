package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * Every command's help reads as sentences: picocli shows only the first description line in a
 * parent's command list, and prints each line of a description as a line of its own (wrapping it
 * again at the terminal width). A description cut into pieces by hand therefore shows a summary
 * that stops mid-sentence ("... and print") and a ragged paragraph.
 */
class HelpTextTest {
  @Test
  void everyDescriptionLineEndsASentenceOrIntroducesWhatFollows() {
    List<String> cut = new ArrayList<>();
    walk(Main.commandLine(), cut);
    assertThat(cut).as("description lines that stop mid-sentence").isEmpty();
  }

  @Test
  void everySubcommandSummaryIsOneWholeSentence() {
    List<String> bad = new ArrayList<>();
    summaries(Main.commandLine(), bad);
    assertThat(bad).isEmpty();
  }

  private static void walk(CommandLine cl, List<String> cut) {
    String[] lines = cl.getCommandSpec().usageMessage().description();
    for (int i = 0; i < lines.length; i++) {
      String line = lines[i].strip();
      if (line.isEmpty() || endsAThought(line) || isOutputFormat(line) || isPicocliOwn(cl)) {
        continue;
      }
      cut.add(cl.getCommandSpec().qualifiedName() + ": \"" + line + "\"");
    }
    cl.getSubcommands().values().stream().distinct().forEach(sub -> walk(sub, cut));
  }

  private static void summaries(CommandLine cl, List<String> bad) {
    for (CommandLine sub : cl.getSubcommands().values()) {
      String[] lines = sub.getCommandSpec().usageMessage().description();
      if (sub.getCommandSpec().name().equals("help")) {
        continue;
      }
      if (lines.length == 0 || !lines[0].strip().endsWith(".")) {
        bad.add(sub.getCommandSpec().qualifiedName() + ": " + (lines.length == 0 ? "(none)" : lines[0]));
      }
      summaries(sub, bad);
    }
  }

  /** A line showing what a command prints, such as {@code fps=X frames=N}: kept whole, as is. */
  private static boolean isOutputFormat(String line) {
    String body = line.startsWith("Output:") ? line.substring("Output:".length()).strip() : line;
    String[] tokens = body.split("\\s+");
    for (String t : tokens) {
      if (!t.contains("=")) {
        return false;
      }
    }
    return true;
  }

  /** picocli's own {@code help} command. */
  private static boolean isPicocliOwn(CommandLine cl) {
    return cl.getCommand() instanceof CommandLine.HelpCommand;
  }

  private static boolean endsAThought(String line) {
    char last = line.charAt(line.length() - 1);
    return ".:;!?)".indexOf(last) >= 0;
  }
}
