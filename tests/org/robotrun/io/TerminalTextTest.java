package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class TerminalTextTest {
  @Test
  void plainTextIsUnchanged() {
    String s = "PICK.LS:3: unknown label LBL[9]\nsecond line\twith a tab";
    assertThat(TerminalText.safe(s)).isSameAs(s);
  }

  @Test
  void controlAndFormatCharactersAreEscaped() {
    assertThat(TerminalText.safe("a\u001b[2Jb")).isEqualTo("a\\e[2Jb");
    assertThat(TerminalText.safe("x\ry")).isEqualTo("x\\ry");
    assertThat(TerminalText.safe("bell\u0007 csi\u009b del\u007f")).isEqualTo("bell\\u0007 csi\\u009B del\\u007F");
    assertThat(TerminalText.safe("rtl\u202eevil")).isEqualTo("rtl\\u202Eevil");
    assertThat(TerminalText.safe("lone\ud800")).isEqualTo("lone\\uD800");
    assertThat(TerminalText.safe("crlf\r\nnext")).isEqualTo("crlf\r\nnext");
    assertThat(TerminalText.safe("Grüße ok")).isEqualTo("Grüße ok");
  }

  @Test
  void longNamesAndLinesAreShortenedWithAnEllipsis() {
    String name = "N".repeat(5000);
    String out = TerminalText.safe("no program named " + name + " here");
    assertThat(out).startsWith("no program named NNN").endsWith("N here").contains("…");
    assertThat(out.length()).isLessThan(200);
    String words = "word ".repeat(1000);
    assertThat(TerminalText.safe(words).length()).isLessThanOrEqualTo(TerminalText.MAX_LINE + 1);
  }
}
