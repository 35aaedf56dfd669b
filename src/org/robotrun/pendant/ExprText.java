package org.robotrun.pendant;

import java.util.Locale;
import java.util.Objects;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;

/**
 * Expressions and bracketed items as the pendant shows them ({@code R[1:COUNT]+1},
 * {@code (DI[1]=ON AND R[2]<>0)}) and as the operator types them into a field. The .LS writer
 * in {@code io} has its own printer; the pendant cannot import {@code io}, and an edited field
 * needs the reverse direction (typed text to an {@link Expr}), which the file reader does for
 * whole lines only.
 */
public final class ExprText {
  private ExprText() {}

  /** Why typed text is not an expression: the message names the column and what was expected. */
  public static final class BadText extends Exception {
    private final boolean namesField;

    BadText(String message) {
      this(message, false);
    }

    /** {@code namesField}: the message starts with the field's name, so it needs no "Bad value" in front. */
    BadText(String message, boolean namesField) {
      super(message);
      this.namesField = namesField;
    }

    /** The text for the prompt line (one line, the field named). */
    String promptText() {
      return namesField ? getMessage() : "Bad value: " + getMessage();
    }
  }

  // ---- formatting ----------------------------------------------------------------------------

  /** The expression as the pendant shows it. */
  public static String format(Expr e) {
    return switch (e) {
      case Expr.IntConst c -> Integer.toString(c.value());
      case Expr.RealConst c -> real(c.value());
      case Expr.OnOff o -> o.on() ? "ON" : "OFF";
      case Expr.StringConst s -> "'" + s.value() + "'";
      case Expr.Register r -> item("R", r.register());
      case Expr.PosElement p -> "PR[" + index(p.register().index()) + "," + p.element()
          + comment(p.register().comment()) + "]";
      case Expr.Io io -> item(io.kind().name(), io.port());
      case Expr.Timer t -> item("TIMER", t.timer());
      case Expr.Arg a -> "AR[" + index(a.index()) + "]";
      case Expr.SysVar v -> v.name();
      case Expr.Unary u -> u.op().symbol() + format(u.operand());
      case Expr.Binary b -> format(b.left()) + binary(b.op()) + format(b.right());
      case Expr.Group g -> "(" + format(g.inner()) + ")";
    };
  }

  private static String binary(Expr.BinaryOp op) {
    return switch (op) {
      case AND, OR, DIV, MOD -> " " + op.symbol() + " ";
      default -> op.symbol();
    };
  }

  /** A real the shortest way that reads back the same ({@code 2.5}, {@code 3.0}). */
  public static String real(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e9) {
      return String.format(Locale.ROOT, "%.1f", v);
    }
    return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
  }

  /** A number without needless decimals ({@code 100}, {@code 0.5}). */
  public static String plain(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e9) {
      return Long.toString((long) v);
    }
    return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
  }

  /** {@code KIND[index:comment]}. */
  public static String item(String kind, Item item) {
    return kind + "[" + index(item.index()) + comment(item.comment()) + "]";
  }

  /** {@code LBL[n:comment]}. */
  public static String label(LabelRef l) {
    return "LBL[" + index(l.index()) + comment(l.comment()) + "]";
  }

  /** {@code 5} or {@code R[2]}. */
  public static String index(Index i) {
    return switch (i) {
      case Index.Direct d -> Integer.toString(d.value());
      case Index.Indirect r -> "R[" + r.register() + comment(r.comment()) + "]";
    };
  }

  private static String comment(String c) {
    return c.isEmpty() ? "" : ":" + c;
  }

  // ---- parsing -------------------------------------------------------------------------------

  /** Parses a typed expression ({@code R[2]+1}, {@code (DI[1]=ON AND R[3]>2)}). */
  public static Expr parse(String text) throws BadText {
    Parser p = new Parser(text);
    Expr e = p.expr(1);
    p.expectEnd();
    // The controller's entry rules (program.EntryRules): refused here as the pendant does.
    java.util.Optional<String> refused = org.robotrun.program.EntryRules.refusal(e);
    if (refused.isPresent()) {
      String r = refused.get();
      throw new BadText(Character.toUpperCase(r.charAt(0)) + r.substring(1));
    }
    return e;
  }

  /** Parses {@code 5} or {@code R[2]} (an index or "n | R[i]" operand). */
  public static Index parseIndex(String text) throws BadText {
    Parser p = new Parser(text);
    Index i = p.index();
    p.expectEnd();
    return i;
  }

  /** Parses an item of the given kind: {@code R[3]}, {@code R[3:COUNT]}, or just {@code 3}. */
  public static Item parseItem(String kind, String text) throws BadText {
    String t = text.trim();
    if (!t.isEmpty() && Character.isDigit(t.charAt(0))) {
      Item item = new Item(parseIndex(t), "");
      checkRange(kind, item.index());
      return item;
    }
    Parser p = new Parser(t);
    p.expectWord(kind);
    Item item = p.bracketItem(kind);
    p.expectEnd();
    return item;
  }

  /** Highest index of each table (Registers' sizes), for entry checks. */
  private static int size(String kind) {
    return switch (kind) {
      case "R" -> org.robotrun.program.Registers.R_COUNT;
      case "PR" -> org.robotrun.program.Registers.PR_COUNT;
      case "TIMER" -> org.robotrun.program.Registers.TIMER_COUNT;
      case "F" -> org.robotrun.program.IoRanges.MAX_SIZE;
      // The controller's I/O sizes are configured per cell; beyond them the line alarms when it runs.
      case "DI", "DO", "RI", "RO", "GI", "GO" -> org.robotrun.program.IoRanges.MAX_SIZE;
      default -> Integer.MAX_VALUE;
    };
  }

  /** A direct index outside its table is refused at entry (the controller would alarm at run time). */
  private static void checkRange(String kind, Index i) throws BadText {
    int n = switch (i) {
      case Index.Direct d -> d.value();
      case Index.Indirect r -> r.register();
    };
    String table = i instanceof Index.Indirect ? "R" : kind;
    if (n < 1 || n > size(table)) {
      throw new BadText(table + "[" + n + "]: index out of range (1.." + size(table) + ")");
    }
  }

  private static final class Parser {
    private final String s;
    private int pos;
    // The same limits as the .LS reader and writer (program.TpLimits): what is typed here reads back.
    private int nesting;
    private int operators;

    private void deeper() throws BadText {
      if (++nesting > org.robotrun.program.TpLimits.MAX_NESTING) {
        throw new BadText("Expression nested too deeply: at most " + org.robotrun.program.TpLimits.MAX_NESTING
            + " levels of parentheses and signs");
      }
    }

    private void countOperator() throws BadText {
      if (++operators > org.robotrun.program.TpLimits.MAX_OPERATORS) {
        throw new BadText("Expression too long: at most " + org.robotrun.program.TpLimits.MAX_OPERATORS + " operators");
      }
    }

    Parser(String s) {
      this.s = Objects.requireNonNull(s, "s");
    }

    private BadText error(String expected) {
      String found = pos >= s.length() ? "end of text" : "'" + s.substring(pos, Math.min(s.length(), pos + 8)) + "'";
      return new BadText("column " + (pos + 1) + ": expected " + expected + ", found " + found);
    }

    private void skipSpaces() {
      while (pos < s.length() && s.charAt(pos) == ' ') {
        pos++;
      }
    }

    private boolean peek(String t) {
      skipSpaces();
      return s.regionMatches(true, pos, t, 0, t.length());
    }

    private boolean accept(String t) {
      if (peek(t)) {
        pos += t.length();
        return true;
      }
      return false;
    }

    private void expect(String t) throws BadText {
      if (!accept(t)) {
        throw error("'" + t + "'");
      }
    }

    void expectEnd() throws BadText {
      skipSpaces();
      if (pos < s.length()) {
        throw error("end of expression");
      }
    }

    void expectWord(String w) throws BadText {
      skipSpaces();
      String word = peekWord();
      if (!word.equals(w)) {
        throw error(w + "[...]");
      }
      pos += word.length();
    }

    private String peekWord() {
      skipSpaces();
      int e = pos;
      while (e < s.length() && (Character.isLetter(s.charAt(e)) || s.charAt(e) == '_')) {
        e++;
      }
      return s.substring(pos, e).toUpperCase(Locale.ROOT);
    }

    /** Binary operators at or above {@code minPrec}, left-associative (precedence climbing). */
    Expr expr(int minPrec) throws BadText {
      Expr left = unary();
      while (true) {
        Expr.BinaryOp op = peekOperator();
        if (op == null || op.precedence() < minPrec) {
          return left;
        }
        pos += op.symbol().length();
        countOperator();
        Expr right = expr(op.precedence() + 1);
        left = new Expr.Binary(op, left, right);
      }
    }

    private Expr.BinaryOp peekOperator() {
      skipSpaces();
      // two-character symbols first so "<=" is not read as "<"
      for (Expr.BinaryOp op : new Expr.BinaryOp[] {Expr.BinaryOp.LE, Expr.BinaryOp.GE, Expr.BinaryOp.NE}) {
        if (s.startsWith(op.symbol(), pos)) {
          return op;
        }
      }
      for (Expr.BinaryOp op : Expr.BinaryOp.values()) {
        boolean word = Character.isLetter(op.symbol().charAt(0));
        if (word ? peekWord().equals(op.symbol()) : s.startsWith(op.symbol(), pos)) {
          return op;
        }
      }
      return null;
    }

    private Expr unary() throws BadText {
      if (accept("-")) {
        skipSpaces();
        if (pos < s.length() && (Character.isDigit(s.charAt(pos)) || s.charAt(pos) == '.')) {
          Expr n = number();
          return switch (n) {
            case Expr.IntConst i -> new Expr.IntConst(-i.value());
            case Expr.RealConst r -> new Expr.RealConst(-r.value());
            default -> new Expr.Unary(Expr.UnaryOp.MINUS, n);
          };
        }
        countOperator();
        deeper();
        Expr operand = unary();
        nesting--;
        return new Expr.Unary(Expr.UnaryOp.MINUS, operand);
      }
      if (accept("!")) {
        countOperator();
        deeper();
        Expr operand = unary();
        nesting--;
        return new Expr.Unary(Expr.UnaryOp.NOT, operand);
      }
      return primary();
    }

    private Expr primary() throws BadText {
      skipSpaces();
      if (pos >= s.length()) {
        throw error("a value");
      }
      char c = s.charAt(pos);
      if (c == '(') {
        pos++;
        deeper();
        Expr inner = expr(1);
        expect(")");
        nesting--;
        return new Expr.Group(inner);
      }
      if (c == '\'') {
        int end = s.indexOf('\'', pos + 1);
        if (end < 0) {
          throw error("a closing quote");
        }
        String v = s.substring(pos + 1, end);
        pos = end + 1;
        return new Expr.StringConst(v);
      }
      if (Character.isDigit(c) || c == '.') {
        return number();
      }
      if (c == '$') {
        int e = pos + 1;
        while (e < s.length() && (Character.isLetterOrDigit(s.charAt(e)) || s.charAt(e) == '_'
            || (s.charAt(e) == '.' && e + 1 < s.length() && s.charAt(e + 1) == '$') || s.charAt(e) == '$')) {
          e++;
        }
        String name = s.substring(pos, e);
        java.util.Optional<String> known = org.robotrun.program.SystemVariables.supported(name);
        if (known.isEmpty()) {
          throw error("a system variable RobotRun runs (" + String.join(", ", org.robotrun.program.SystemVariables.SUPPORTED) + ")");
        }
        pos = e;
        return new Expr.SysVar(known.get());
      }
      String w = peekWord();
      switch (w) {
        case "ON", "OFF" -> {
          pos += w.length();
          return new Expr.OnOff(w.equals("ON"));
        }
        case "R" -> {
          pos += 1;
          return new Expr.Register(bracketItem("R"));
        }
        case "PR" -> {
          pos += 2;
          expect("[");
          Index i = index();
          checkRange("PR", i);
          expect(",");
          int element = integer();
          if (element < 1 || element > 6) {
            throw error("element 1..6");
          }
          String comment = commentIfAny();
          expect("]");
          return new Expr.PosElement(new Item(i, comment), element);
        }
        case "TIMER" -> {
          pos += 5;
          return new Expr.Timer(bracketItem("TIMER"));
        }
        case "AR" -> {
          pos += 2;
          expect("[");
          Index i = index();
          expect("]");
          return new Expr.Arg(i);
        }
        default -> {
          for (IoKind k : IoKind.values()) {
            if (w.equals(k.name())) {
              pos += w.length();
              return new Expr.Io(k, bracketItem(k.name()));
            }
          }
          throw error("a number, ON/OFF, R[i], PR[i,j], DI/DO/RI/RO/GI/GO/F[i], TIMER[i], AR[i] or (");
        }
      }
    }

    private Expr number() throws BadText {
      int start = pos;
      while (pos < s.length() && (Character.isDigit(s.charAt(pos)) || s.charAt(pos) == '.')) {
        pos++;
      }
      String t = s.substring(start, pos);
      try {
        if (t.contains(".")) {
          double v = Double.parseDouble(t);
          if (Double.isInfinite(v)) {
            // hundreds of digits: the .LS reader refuses such a number, so the pendant does too
            pos = start;
            throw error("a number of at most 308 digits");
          }
          return new Expr.RealConst(v);
        }
        return new Expr.IntConst(Integer.parseInt(t));
      } catch (NumberFormatException e) {
        pos = start;
        throw error("a number");
      }
    }

    int integer() throws BadText {
      skipSpaces();
      int start = pos;
      while (pos < s.length() && Character.isDigit(s.charAt(pos))) {
        pos++;
      }
      if (start == pos) {
        throw error("a whole number");
      }
      try {
        return Integer.parseInt(s.substring(start, pos));
      } catch (NumberFormatException e) {
        pos = start;
        throw error("a whole number");
      }
    }

    /** {@code [index(:comment)]} of table {@code kind}, range-checked. */
    Item bracketItem(String kind) throws BadText {
      expect("[");
      Index i = index();
      checkRange(kind, i);
      String comment = commentIfAny();
      expect("]");
      return new Item(i, comment);
    }

    private String commentIfAny() {
      skipSpaces();
      if (pos < s.length() && s.charAt(pos) == ':') {
        int end = s.indexOf(']', pos);
        end = end < 0 ? s.length() : end;
        String c = s.substring(pos + 1, end).trim();
        pos = end;
        return c;
      }
      return "";
    }

    /** {@code n} or {@code R[n(:comment)]}. */
    Index index() throws BadText {
      skipSpaces();
      if (peekWord().equals("R")) {
        pos += 1;
        expect("[");
        int r = integer();
        String comment = commentIfAny();
        expect("]");
        return new Index.Indirect(r, comment);
      }
      return new Index.Direct(integer());
    }
  }

}
