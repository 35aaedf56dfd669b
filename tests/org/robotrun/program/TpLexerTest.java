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

  // ---- German listings (docs/tp-language.md, the German keyword table) ----------------------

  @Test
  void germanKeywordsReadAsTheirEnglishFormInAnyCase() {
    assertThat(texts("WARTE E[1]=AN")).containsExactly("WAIT", "DI", "[", "1", "]", "=", "ON", "");
    assertThat(texts("wenn i[2]=1,sprung label[3]")).containsExactly("IF", "R", "[", "2", "]", "=", "1", ",", "JMP", "LBL", "[", "3", "]", "");
    assertThat(texts("A[4]=AUS")).containsExactly("DO", "[", "4", "]", "=", "OFF", "");
    assertThat(texts("gA[1]=gE[2]")).containsExactly("GO", "[", "1", "]", "=", "GI", "[", "2", "]", "");
    assertThat(texts("BALM[1]")).containsExactly("UALM", "[", "1", "]", "");
    assertThat(texts("TIMER[1]=STOPP")).containsExactly("TIMER", "[", "1", "]", "=", "STOP", "");
  }

  @Test
  void aGermanKindIsAKindOnlyRightBeforeItsBracket() {
    // "A P[1] ..." is an arc motion, not an output; "E" alone is a word
    assertThat(texts("A P[1] 100mm/sec FINE")).startsWith("A", "P", "[");
    assertThat(texts("A [1]")).startsWith("A", "[");
    assertThat(texts("R[1]=E")).containsExactly("R", "[", "1", "]", "=", "E", "");
    // a system variable is never a German kind: $E[X] keeps its name
    assertThat(texts("$E[X]")).startsWith("$E", "[");
  }

  @Test
  void aGermanKeywordAfterCallOrRunIsAProgramName() {
    assertThat(texts("AUFRUF WARTE")).containsExactly("CALL", "WARTE", "");
    assertThat(texts("RUN ENDE")).containsExactly("RUN", "ENDE", "");
    assertThat(texts("CALL ENDE")).containsExactly("CALL", "ENDE", "");
    assertThat(texts("ENDE")).containsExactly("END", "");
  }

  @Test
  void germanUnlockPregAndTheBracketedAndOr() {
    assertThat(texts("FREIG. PREG")).containsExactly("UNLOCK", "PREG", "");
    assertThat(texts("freig.PREG")).containsExactly("UNLOCK", "PREG", "");
    assertThat(texts("FREIG PREG")).containsExactly("FREIG", "PREG", "");
    List<TpToken> t = TpLexer.tokenize("E[1] [&] E[2] [+] E[3]", 1, 1, true);
    assertThat(t).extracting(TpToken::text).containsExactly("DI", "[", "1", "]", "AND", "DI", "[", "2", "]", "OR", "DI", "[", "3", "]", "");
    assertThat(t.get(4).column()).isEqualTo(6);
    assertThat(t.get(4).kind()).isEqualTo(Kind.WORD);
    assertThat(t.get(5).column()).isEqualTo(10);
    // only "[&]" and "[+]" are the operators: "[-]" and "[&" are brackets
    assertThat(texts("[-]")).containsExactly("[", "-", "]", "");
    assertThat(texts("[&")).containsExactly("[", "&", "");
  }

  // ---- remarks, markers, free text --------------------------------------------------------

  @Test
  void remarkLinesKeepTheirTextAndItsColumn() {
    List<TpToken> bang = TpLexer.tokenize("  ! why", 4, 5, true);
    assertThat(bang).extracting(TpToken::kind).containsExactly(Kind.BANG, Kind.RAW, Kind.EOL);
    assertThat(bang.get(0).column()).isEqualTo(7);
    assertThat(bang.get(1).column()).isEqualTo(8);
    assertThat(bang.get(1).text()).isEqualTo(" why");
    assertThat(bang.get(2).column()).isEqualTo(12);
    List<TpToken> dashes = TpLexer.tokenize("--eg:ARC ON", 1, 1, true);
    assertThat(dashes).extracting(TpToken::text).containsExactly("--", "eg:ARC ON", "");
    assertThat(dashes.get(0).kind()).isEqualTo(Kind.MINUS);
    assertThat(dashes.get(1).column()).isEqualTo(3);
    List<TpToken> slashes = TpLexer.tokenize("//R[1]=2", 1, 1, true);
    assertThat(slashes).extracting(TpToken::text).containsExactly("//", "R[1]=2", "");
    assertThat(slashes.get(1).column()).isEqualTo(3);
    // only at the start of a statement: elsewhere they are operators
    assertThat(kinds("R[1]=1--1")).containsSubsequence(Kind.MINUS, Kind.MINUS, Kind.NUMBER).doesNotContain(Kind.RAW);
    assertThat(kinds("R[1]=2//1")).containsSubsequence(Kind.SLASH, Kind.SLASH).doesNotContain(Kind.RAW);
    assertThat(TpLexer.tokenize("! x", 1, 1, false)).extracting(TpToken::kind).containsExactly(Kind.BANG, Kind.WORD, Kind.EOL);
    assertThat(TpLexer.tokenize("// x", 1, 1, false)).extracting(TpToken::kind)
        .containsExactly(Kind.SLASH, Kind.SLASH, Kind.WORD, Kind.EOL);
    // a single '-' or '/' at the start is a token of its own
    assertThat(kinds("-1")).containsExactly(Kind.MINUS, Kind.NUMBER, Kind.EOL);
    assertThat(kinds("/1")).containsExactly(Kind.SLASH, Kind.NUMBER, Kind.EOL);
    assertThat(kinds("-")).containsExactly(Kind.MINUS, Kind.EOL);
    assertThat(kinds("/")).containsExactly(Kind.SLASH, Kind.EOL);
  }

  @Test
  void theControllersCurrentPointMarkerIsDropped() {
    List<TpToken> t = TpLexer.tokenize("J @P[3] 100% FINE", 1, 1, true);
    assertThat(t).extracting(TpToken::text).containsExactly("J", "P", "[", "3", "]", "100", "%", "FINE", "");
    assertThat(t.get(1).column()).isEqualTo(4);
    assertThat(texts("J @p[3]")).startsWith("J", "p", "[");
    // '@' before anything else is a bad character, also at the end of the line
    assertThat(kinds("@R")).containsExactly(Kind.BAD_CHAR, Kind.WORD, Kind.EOL);
    assertThat(kinds("R@")).containsExactly(Kind.WORD, Kind.BAD_CHAR, Kind.EOL);
  }

  @Test
  void messageTextRunsToTheLastBracketAndMayBeEmpty() {
    assertThat(TpLexer.tokenize("MESSAGE[R[1] > 5 mm]", 1, 1, true)).extracting(TpToken::text)
        .containsExactly("MESSAGE", "[", "R[1] > 5 mm", "]", "");
    List<TpToken> empty = TpLexer.tokenize("MESSAGE[]", 1, 1, true);
    assertThat(empty).extracting(TpToken::kind).containsExactly(Kind.WORD, Kind.LBRACKET, Kind.RAW, Kind.RBRACKET, Kind.EOL);
    assertThat(empty.get(2).text()).isEmpty();
    assertThat(empty.get(2).column()).isEqualTo(9);
    List<TpToken> open = TpLexer.tokenize("MESSAGE[no end", 1, 1, true);
    assertThat(open).extracting(TpToken::kind).containsExactly(Kind.WORD, Kind.LBRACKET, Kind.RAW, Kind.EOL);
    assertThat(open.get(2).text()).isEqualTo("no end");
    // a ']' before the '[' does not end the text
    assertThat(TpLexer.tokenize("] MESSAGE[x", 1, 1, true)).extracting(TpToken::text).containsExactly("]", "MESSAGE", "[", "x", "");
  }

  @Test
  void anItemCommentEndsAtTheBracketThatClosesItsItem() {
    assertThat(texts("R[103:Z-PR[38]]=1")).containsExactly("R", "[", "103", ":", "Z-PR[38]", "]", "=", "1", "");
    List<TpToken> t = TpLexer.tokenize("R[2:A:B]", 1, 1, true);
    assertThat(t.get(4).kind()).isEqualTo(Kind.ITEM_COMMENT);
    assertThat(t.get(4).text()).isEqualTo("A:B");
    assertThat(t.get(4).column()).isEqualTo(5);
    // unbalanced: the first ']' ends it
    assertThat(texts("R[1:a[b]")).containsExactly("R", "[", "1", ":", "a[b", "]", "");
    // no ']' at all: to the end of the line
    assertThat(texts("R[1:abc")).containsExactly("R", "[", "1", ":", "abc", "");
    // an empty comment
    assertThat(kinds("R[1:]")).containsExactly(Kind.WORD, Kind.LBRACKET, Kind.NUMBER, Kind.COLON, Kind.ITEM_COMMENT, Kind.RBRACKET, Kind.EOL);
  }

  @Test
  void aColonOutsideBracketsOrAfterAMotionGroupIsNoComment() {
    assertThat(kinds("A:B")).containsExactly(Kind.WORD, Kind.COLON, Kind.WORD, Kind.EOL);
    assertThat(texts("PR[GP1:5,3:Z]")).containsExactly("PR", "[", "GP1", ":", "5", ",", "3", ":", "Z", "]", "");
    assertThat(kinds("PR[gp9:1]")).containsExactly(Kind.WORD, Kind.LBRACKET, Kind.WORD, Kind.COLON, Kind.NUMBER, Kind.RBRACKET, Kind.EOL);
    // GP0, GPX and GP10 are no motion groups: what follows is a comment
    for (String g : List.of("GP0", "GPX", "GP10", "XP1", "GX1")) {
      assertThat(kinds("PR[" + g + ":1]")).as(g).contains(Kind.ITEM_COMMENT);
    }
    // a stray ']' does not close a bracket that was never opened
    assertThat(kinds("]R[1:X]")).contains(Kind.ITEM_COMMENT);
    assertThat(kinds("R[1]:X")).doesNotContain(Kind.ITEM_COMMENT);
  }

  // ---- words, numbers, strings ------------------------------------------------------------

  @Test
  void systemVariablePathsAreOneWord() {
    for (String v : List.of("$MCR.$GENOVERRIDE", "$MNUTOOLNUM[1]", "$MIX_BG[2].$STATUS", "$SYSTEM_TIME[1].RUN_TOT",
        "$[PROG]NAME", "$SGSCH1[90].$WELD_PRESS", "$A[12][3]")) {
      assertThat(texts(v + "=1")).as(v).containsExactly(v, "=", "1", "");
    }
    // an index that is not a number, an empty KAREL program name, a dot before no name end the word
    assertThat(texts("$X[R[1]]")).startsWith("$X", "[", "R");
    assertThat(texts("$X[]")).startsWith("$X", "[", "]");
    assertThat(texts("$X[1")).startsWith("$X", "[", "1");
    assertThat(texts("$[]X")).startsWith("$", "[", "]", "X");
    assertThat(texts("$[A B]X")).startsWith("$", "[", "A", "B");
    assertThat(texts("$[A]")).containsExactly("$[A]", "");
    assertThat(texts("$X.")).containsExactly("$X", ".", "");
    assertThat(texts("$X.1")).containsExactly("$X", ".1", "");
    assertThat(texts("$X._Y")).containsExactly("$X._Y", "");
  }

  @Test
  void numbersAreDigitsWithAtMostOnePoint() {
    assertThat(texts("1.5 .5 7. 12 3.4.5")).containsExactly("1.5", ".5", "7.", "12", "3.4", ".5", "");
    assertThat(kinds(".")).containsExactly(Kind.BAD_CHAR, Kind.EOL);
    assertThat(kinds(".x")).containsExactly(Kind.BAD_CHAR, Kind.WORD, Kind.EOL);
    assertThat(texts("9")).containsExactly("9", "");
    assertThat(texts("0")).containsExactly("0", "");
    assertThat(texts("x9_a")).containsExactly("x9_a", "");
    assertThat(texts("_a Z z")).containsExactly("_a", "Z", "z", "");
  }

  @Test
  void stringsTakeEitherQuoteAndAnUnclosedOneIsABadCharacter() {
    List<TpToken> t = TpLexer.tokenize("SR[1]='A B'+\"it's\"", 1, 1, true);
    assertThat(t).extracting(TpToken::kind).containsExactly(Kind.WORD, Kind.LBRACKET, Kind.NUMBER, Kind.RBRACKET, Kind.EQ,
        Kind.STRING, Kind.PLUS, Kind.STRING, Kind.EOL);
    assertThat(t.get(5).text()).isEqualTo("A B");
    assertThat(t.get(7).text()).isEqualTo("it's");
    assertThat(t.get(7).column()).isEqualTo(13);
    assertThat(kinds("''")).containsExactly(Kind.STRING, Kind.EOL);
    List<TpToken> open = TpLexer.tokenize("'AB", 1, 1, true);
    assertThat(open).extracting(TpToken::kind).containsExactly(Kind.BAD_CHAR, Kind.WORD, Kind.EOL);
    assertThat(open.get(1).column()).isEqualTo(2);
  }

  @Test
  void everyPunctuationCharacterHasItsKind() {
    assertThat(kinds("()[]{},;=+-*/%!")).containsExactly(Kind.LPAREN, Kind.RPAREN, Kind.LBRACKET, Kind.RBRACKET, Kind.LBRACE,
        Kind.RBRACE, Kind.COMMA, Kind.SEMICOLON, Kind.EQ, Kind.PLUS, Kind.MINUS, Kind.STAR, Kind.SLASH, Kind.PERCENT,
        Kind.BANG, Kind.EOL);
    assertThat(texts("<>1<=2>=3<")).containsExactly("<>", "1", "<=", "2", ">=", "3", "<", "");
    assertThat(texts(">")).containsExactly(">", "");
    assertThat(TpLexer.tokenize("R[1]=\u00e9", 1, 1, true).get(5).text()).isEqualTo("\u00e9");
    assertThat(TpLexer.tokenize("R[1]=\u00e9", 1, 1, true).get(5).describe()).isEqualTo("character U+00E9");
  }

  @Test
  void tabsSeparateTokensAndTheEndOfLineStandsAfterTheText() {
    List<TpToken> t = TpLexer.tokenize("\tJ\tP[1]  ", 9, 3, true);
    assertThat(t).extracting(TpToken::text).containsExactly("J", "P", "[", "1", "]", "");
    assertThat(t.get(0).column()).isEqualTo(4);
    assertThat(t.get(5).column()).isEqualTo(12);
    assertThat(t).extracting(TpToken::line).containsOnly(9);
  }

  // ---- how tokens are named in messages ---------------------------------------------------

  @Test
  void tokensAreNamedInMessagesClippedToFortyCharacters() {
    assertThat(new TpToken(Kind.EOL, "", 1, 1).describe()).isEqualTo("end of line");
    assertThat(new TpToken(Kind.STRING, "AB", 1, 1).describe()).isEqualTo("'AB'");
    assertThat(new TpToken(Kind.ITEM_COMMENT, "HOME", 1, 1).describe()).isEqualTo("comment ':HOME'");
    assertThat(new TpToken(Kind.RAW, "anything", 1, 1).describe()).isEqualTo("text");
    assertThat(new TpToken(Kind.WORD, "FOO", 1, 1).describe()).isEqualTo("'FOO'");
    assertThat(new TpToken(Kind.BAD_CHAR, "#", 1, 1).describe()).isEqualTo("character '#'");
    assertThat(new TpToken(Kind.BAD_CHAR, " ", 1, 1).describe()).isEqualTo("character ' '");
    assertThat(new TpToken(Kind.BAD_CHAR, "~", 1, 1).describe()).isEqualTo("character '~'");
    assertThat(new TpToken(Kind.BAD_CHAR, "\u001f", 1, 1).describe()).isEqualTo("character U+001F");
    assertThat(new TpToken(Kind.BAD_CHAR, "\u007f", 1, 1).describe()).isEqualTo("character U+007F");
    assertThat(new TpToken(Kind.BAD_CHAR, "", 1, 1).describe()).isEqualTo("character U+0000");
    String forty = "A".repeat(40);
    assertThat(TpToken.clip(forty)).isEqualTo(forty);
    assertThat(TpToken.clip(forty + "B")).isEqualTo(forty + "...");
    assertThat(new TpToken(Kind.WORD, forty + "BC", 1, 1).describe()).isEqualTo("'" + forty + "...'");
    assertThat(new TpToken(Kind.STRING, forty + "BC", 1, 1).describe()).isEqualTo("'" + forty + "...'");
    assertThat(new TpToken(Kind.ITEM_COMMENT, forty + "BC", 1, 1).describe()).isEqualTo("comment ':" + forty + "...'");
  }

  @Test
  void wordsCompareWithoutCaseAndOnlyAsWords() {
    assertThat(new TpToken(Kind.WORD, "fine", 1, 1).isWord("FINE")).isTrue();
    assertThat(new TpToken(Kind.STRING, "FINE", 1, 1).isWord("FINE")).isFalse();
    assertThat(new TpToken(Kind.WORD, "FINE", 1, 1).is(Kind.WORD)).isTrue();
    assertThat(new TpToken(Kind.WORD, "FINE", 1, 1).is(Kind.STRING)).isFalse();
  }

  @Test
  void edgesOfTheLine() {
    // a '$' or a German group bracket at the very start or end of the text
    assertThat(texts("$")).containsExactly("$", "");
    assertThat(texts("$.1")).containsExactly("$", ".1", "");
    assertThat(kinds("[GP1:5]")).containsExactly(Kind.LBRACKET, Kind.WORD, Kind.COLON, Kind.NUMBER, Kind.RBRACKET, Kind.EOL);
    // the first character beyond ASCII is a bad character, not a crash
    assertThat(TpLexer.tokenize("\u0080", 1, 1, true)).extracting(TpToken::kind).containsExactly(Kind.BAD_CHAR, Kind.EOL);
    assertThat(TpLexer.tokenize("\u007f", 1, 1, true).get(0).text()).isEqualTo("\u007f");
  }
}
