package org.robotrun.program;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.program.TpToken.Kind;

/**
 * A position in a token list ending with {@link Kind#EOL}, with the look-ahead and "expected X,
 * found Y" helpers both .LS parsers use. Reading past the end keeps returning the final EOL, so
 * a parser never runs off its input.
 */
public abstract class TpTokenCursor {
  protected final List<TpToken> tokens;
  private int pos;

  /** @param tokens the tokens; must end with an {@link Kind#EOL} token */
  protected TpTokenCursor(List<TpToken> tokens) {
    this.tokens = tokens;
  }

  /** An empty cursor whose tokens are added later (the last one added must be an EOL). */
  protected TpTokenCursor() {
    this(new ArrayList<>());
  }

  protected final TpToken peek() {
    return tokens.get(pos);
  }

  protected final TpToken peek(int ahead) {
    return tokens.get(Math.min(pos + ahead, tokens.size() - 1));
  }

  protected final TpToken next() {
    TpToken t = tokens.get(pos);
    if (pos < tokens.size() - 1) {
      pos++;
    }
    return t;
  }

  protected final boolean accept(Kind k) {
    if (peek().is(k)) {
      next();
      return true;
    }
    return false;
  }

  protected final TpToken expect(Kind k, String what) {
    if (!peek().is(k)) {
      throw error("expected " + what + ", found " + peek().describe());
    }
    return next();
  }

  protected final TpToken expectWord(String what) {
    return expect(Kind.WORD, what);
  }

  protected final void expectWordNamed(String word, String what) {
    if (!peek().isWord(word)) {
      throw error("expected " + what + ", found " + peek().describe());
    }
    next();
  }

  /** An error on the line of the next token. */
  protected final TpSyntaxError error(String message) {
    return TpSyntaxError.at(peek().line(), peek().column(), message);
  }

  protected static TpSyntaxError error(TpToken at, String message) {
    return TpSyntaxError.at(at.line(), at.column(), message);
  }

  /** A form the controller has and RobotRun does not run, at {@code at}. */
  protected static TpSyntaxError unsupported(TpToken at, String what, boolean runnable) {
    return TpSyntaxError.unsupported(at.line(), at.column(), what, runnable);
  }
}
