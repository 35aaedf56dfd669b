package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.program.TpToken.Kind;

class TpLexerTest {

  private static List<Kind> kinds(String text) {
    return TpLexer.tokenize(text, 7, 1, true).stream().map(TpToken::kind).toList();
  }

  private static List<String> texts(String text) {
    return TpLexer.tokenize(text, 7, 1, true).stream().map(TpToken::text).toList();
  }

  @Test
  void motionLineSplitsIntoWordsNumbersAndPunctuation() {
    assertThat(texts("J P[1:HOME] 30% FINE    ;"))
        .containsExactly("J", "P", "[", "1", ":", "HOME", "]", "30", "%", "FINE", ";", "");
    assertThat(texts("L P[2] 400mm/sec CNT50"))
        .containsExactly("L", "P", "[", "2", "]", "400", "mm", "/", "sec", "CNT50", "");
  }

  @Test
  void itemCommentIsFreeTextUpToTheClosingBracket() {
    List<TpToken> t = TpLexer.tokenize("LBL[99:NO GRIP: really]", 3, 8, true);
    assertThat(t.get(4).kind()).isEqualTo(Kind.ITEM_COMMENT);
    assertThat(t.get(4).text()).isEqualTo("NO GRIP: really");
    assertThat(t.get(5).kind()).isEqualTo(Kind.RBRACKET);
  }

  @Test
  void nestedIndirectItemKeepsBothComments() {
    assertThat(texts("R[R[1:I]:X]=1"))
        .containsExactly("R", "[", "R", "[", "1", ":", "I", "]", ":", "X", "]", "=", "1", "");
  }

  @Test
  void remarkAndCommentedOutLineAreRawText() {
    assertThat(kinds("! stack three parts ")).containsExactly(Kind.BANG, Kind.RAW, Kind.EOL);
    assertThat(texts("! stack three parts ").get(1)).isEqualTo(" stack three parts ");
    assertThat(kinds("//L P[1] 100mm/sec FINE")).containsExactly(Kind.SLASH, Kind.RAW, Kind.EOL);
  }

  @Test
  void bangInsideAnExpressionIsNot() {
    assertThat(kinds("F[1]=(!DI[1])")).contains(Kind.BANG).doesNotContain(Kind.RAW);
  }

  @Test
  void messageTextIsRaw() {
    List<TpToken> t = TpLexer.tokenize("MESSAGE[Gripper did not close: R1]", 1, 1, true);
    assertThat(t).extracting(TpToken::kind)
        .containsExactly(Kind.WORD, Kind.LBRACKET, Kind.RAW, Kind.RBRACKET, Kind.EOL);
    assertThat(t.get(2).text()).isEqualTo("Gripper did not close: R1");
  }

  @Test
  void comparisonOperatorsAndNumbersWithoutLeadingZero() {
    assertThat(kinds("<> <= >= < > =")).containsExactly(
        Kind.NE, Kind.LE, Kind.GE, Kind.LT, Kind.GT, Kind.EQ, Kind.EOL);
    assertThat(texts("WAIT    .20(sec)")).containsExactly("WAIT", ".20", "(", "sec", ")", "");
  }

  @Test
  void columnsAreOneBasedAndOffsetByTheLineStart() {
    List<TpToken> t = TpLexer.tokenize("UFRAME_NUM=1", 2, 8, true);
    assertThat(t.get(0).column()).isEqualTo(8);
    assertThat(t.get(1).column()).isEqualTo(18);
    assertThat(t.get(2).line()).isEqualTo(2);
  }

  @Test
  void strangeCharactersBecomeBadCharTokensNotExceptions() {
    assertThat(kinds("R[1]=\u0000\u00ff#")).containsSubsequence(Kind.BAD_CHAR, Kind.BAD_CHAR, Kind.BAD_CHAR);
    assertThat(kinds("CONFIG : 'N U T")).contains(Kind.BAD_CHAR);
  }
}
