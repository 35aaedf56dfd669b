package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * Issue 29 walkthrough: the window's font (Latin-1) drew the lab steps' arrows and minus signs as
 * '?' ("COORD twice: JOINT ? JGFRM ? WORLD", "+X/?X (Q/A)").
 */
class TxtPlainTest {
  @Test
  void charactersTheFontLacksAreSpelledInAscii() {
    assertThat(Txt.plain("JOINT \u2192 JGFRM \u2192 WORLD")).isEqualTo("JOINT -> JGFRM -> WORLD");
    assertThat(Txt.plain("+X/\u2212X (Q/A) \u2264 5 \u2026 \u201cok\u201d \u2014 done")).isEqualTo("+X/-X (Q/A) <= 5 ... \"ok\" - done");
    String latin1 = "J5 -90.000\u00b0 \u00d7 2";
    assertThat(Txt.plain(latin1)).isSameAs(latin1);
  }

  @Test
  void everyLabStepShowsWithoutACharacterTheFontLacks() {
    for (int lab = 1; lab <= 12; lab++) {
      String id = String.format("%02d", lab);
      try (var files = java.nio.file.Files.list(Path.of("docs/labs"))) {
        Path guide = files.filter(f -> f.getFileName().toString().startsWith(id + "-")).findFirst().orElseThrow();
        for (String step : LabsPanel.steps(guide)) {
          assertThat(Txt.plain(step).chars()).as(guide + ": " + step).allMatch(c -> c < 0x100);
        }
      } catch (java.io.IOException e) {
        throw new AssertionError(e);
      }
    }
  }

  @Test
  void theStepsWindowDropsMarkdownEmphasisButKeepsAGroupMask() {
    assertThat(LabsPanel.unmark("MENU, 5 *SETUP Frames*, F1 [TYPE], 1 *Tool Frame*; **bold** `code`"))
        .isEqualTo("MENU, 5 SETUP Frames, F1 [TYPE], 1 Tool Frame; bold code");
    assertThat(LabsPanel.unmark("(`DEFAULT_GROUP = *,*,*,*,*` in its /ATTR)")).isEqualTo("(DEFAULT_GROUP = *,*,*,*,* in its /ATTR)");
    assertThat(LabsPanel.unmark("2 * 3 = 6, a*b")).isEqualTo("2 * 3 = 6, a*b");
  }
}
