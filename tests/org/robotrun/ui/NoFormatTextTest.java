package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Dear ImGui's Text, TextWrapped, TextDisabled, TextColored, BulletText, LabelText and SetTooltip
 * read their text as a printf format; RobotRun's text (scenario descriptions, comments, typed
 * values) may hold a '%'. Only {@link Txt} and textUnformatted may draw text.
 */
class NoFormatTextTest {
  private static final Pattern FORMAT_CALL = Pattern.compile(
      "ImGui\\.(text|textWrapped|textDisabled|textColored|bulletText|labelText|setTooltip)\\(");

  @Test
  void noWindowCodeHandsTextToAnImGuiFormatFunction() throws IOException {
    List<String> hits = new ArrayList<>();
    for (String dir : List.of("src/org/robotrun/ui", "src/org/robotrun/app")) {
      try (Stream<Path> files = Files.walk(Path.of(dir))) {
        for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
          List<String> lines = Files.readAllLines(f);
          for (int i = 0; i < lines.size(); i++) {
            if (FORMAT_CALL.matcher(lines.get(i)).find()) {
              hits.add(f + ":" + (i + 1) + ": " + lines.get(i).trim());
            }
          }
        }
      }
    }
    assertThat(hits).as("use ui.Txt or ImGui.textUnformatted").isEmpty();
  }
}
