package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.CommentTable;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;
import org.robotrun.program.Registers;
import org.robotrun.program.VisionRegisters;
import org.robotrun.program.VisionResult;

/**
 * DATA: numeric registers (value and comment), position registers (summary; DETAIL for
 * components and Cartesian/joint form; RECORD, CLEAR), flags and vision registers (list; DETAIL
 * for the fields iRVision shows: MODELID, ENC, OFFSET, FOUND_POS, MES). [TYPE] switches tables.
 */
final class DataScreen implements Screen {
  enum Table {
    REGISTERS("Numeric Registers", Registers.R_COUNT),
    POSITION_REGISTERS("Position Registers", Registers.PR_COUNT),
    FLAGS("Flags", Registers.FLAG_COUNT),
    VISION_REGISTERS("Vision Reg", VisionRegisters.COUNT);

    final String title;
    final int size;

    Table(String title, int size) {
      this.title = title;
      this.size = size;
    }
  }

  private Table table = Table.REGISTERS;
  private final int[] cursor = new int[Table.values().length];
  /** Column on a register row: 0 comment, 1 value. */
  private int column = 1;
  /** Vision registers: the DETAIL page of the register under the cursor instead of the list. */
  private boolean visionDetail;

  private int index() {
    return cursor[table.ordinal()] + 1;
  }

  @Override
  public String title(Pendant p) {
    return "DATA " + table.title;
  }

  @Override
  public List<String> body(Pendant p) {
    if (table == Table.VISION_REGISTERS && visionDetail) {
      return visionDetail(p.control().registers().vision(), index());
    }
    List<String> rows = new ArrayList<>();
    int cur = cursor[table.ordinal()];
    int top = Math.max(0, Math.min(cur - Lcd.BODY_ROWS / 2, table.size - Lcd.BODY_ROWS));
    Registers regs = p.control().registers();
    for (int i = top; i < table.size && rows.size() < Lcd.BODY_ROWS; i++) {
      int n = i + 1;
      boolean on = i == cur;
      String m = on ? ">" : " ";
      rows.add(switch (table) {
        case REGISTERS -> {
          String c = p.control().comment(CommentTable.R, n);
          String v = regs.isInteger(n) ? Long.toString((long) regs.number(n)) : ExprText.real(regs.number(n));
          yield m + String.format(Locale.ROOT, "R[%3d:%s]  = %s", n, on && column == 0 ? "{" + pad(c) + "}" : pad(c),
              on && column == 1 ? "{" + v + "}" : v);
        }
        case POSITION_REGISTERS -> {
          String c = p.control().comment(CommentTable.PR, n);
          yield m + String.format(Locale.ROOT, "PR[%3d:%s] %s", n, on && column == 0 ? "{" + pad(c) + "}" : pad(c),
              summary(regs.position(n)));
        }
        case FLAGS -> m + String.format(Locale.ROOT, "F[%3d]  %s", n, regs.bit(IoKind.F, n) ? "ON" : "OFF");
        case VISION_REGISTERS -> m + String.format(Locale.ROOT, "VR[%2d] %s", n, regs.vision().get(n)
            .map(r -> "MODELID %d  %s".formatted(r.modelId(), summary(r.offset()))).orElse("(empty)"));
      });
    }
    return rows;
  }

  private static String pad(String c) {
    return String.format(Locale.ROOT, "%-12s", c);
  }

  static String summary(Position pos) {
    return switch (pos) {
      case Position.Cartesian c -> String.format(Locale.ROOT, "X%.1f Y%.1f Z%.1f W%.1f P%.1f R%.1f", c.xMm(), c.yMm(),
          c.zMm(), c.wDeg(), c.pDeg(), c.rDeg());
      case Position.Joint j -> String.format(Locale.ROOT, "JNT %.1f,%.1f,%.1f,%.1f,%.1f,%.1f", j.j1Deg(), j.j2Deg(),
          j.j3Deg(), j.j4Deg(), j.j5Deg(), j.j6Deg());
    };
  }

  /** The DETAIL page of VR[n], fields as iRVision names them. */
  static List<String> visionDetail(VisionRegisters vr, int n) {
    List<String> rows = new ArrayList<>();
    rows.add(String.format(Locale.ROOT, "VR[%d]", n));
    Optional<VisionResult> r = vr.get(n);
    if (r.isEmpty()) {
      rows.add("  (empty: no VISION GET_OFFSET has filled it)");
      return rows;
    }
    VisionResult v = r.get();
    rows.add("  WORKID:      0");
    rows.add("  TYPE:        Fixed frame offset   UF: " + v.userFrame());
    rows.add("  MODELID:     " + v.modelId());
    rows.add("  ENC:         0");
    rows.add("  OFFSET:      " + summary(v.offset()));
    rows.add("  FOUND_POS[1] " + summary(v.found()));
    rows.add(String.format(Locale.ROOT, "  MES[1]:      %.1f (score)", v.score()));
    rows.add("  PROCESS:     " + v.process());
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    if (table == Table.VISION_REGISTERS) {
      return visionDetail ? List.of("[TYPE]", "PREV", "NEXT", "LIST", "") : List.of("[TYPE]", "", "", "DETAIL", "");
    }
    return switch (table) {
      case REGISTERS -> List.of("[TYPE]", "", "", "", "");
      case POSITION_REGISTERS -> List.of("[TYPE]", "DETAIL", "RECORD", "CLEAR", "");
      case FLAGS -> List.of("[TYPE]", "", "", "ON", "OFF");
      case VISION_REGISTERS -> throw new IllegalStateException("handled above");
    };
  }

  @Override
  public void key(Pendant p, Key k) {
    int t = table.ordinal();
    Registers regs = p.control().registers();
    switch (k) {
      case UP -> cursor[t] = Math.max(0, cursor[t] - (p.shift() ? Lcd.BODY_ROWS : 1));
      case DOWN -> cursor[t] = Math.min(table.size - 1, cursor[t] + (p.shift() ? Lcd.BODY_ROWS : 1));
      case LEFT -> column = 0;
      case RIGHT -> column = 1;
      case F1 -> p.choose("TYPE", java.util.Arrays.stream(Table.values()).map(x -> x.title).toList(), i -> {
        table = Table.values()[i];
        visionDetail = false;
      });
      case ITEM -> p.entry("Item number:", "", false, s -> {
        Optional<Integer> n = Pendant.parseInt(s, 1, table.size);
        if (n.isEmpty()) {
          return Optional.of("Item must be 1.." + table.size + ", got '" + s.trim() + "'");
        }
        cursor[t] = n.get() - 1;
        return Optional.empty();
      });
      case F2 -> {
        if (table == Table.POSITION_REGISTERS) {
          PositionScreen.openRegister(p, index());
        } else if (table == Table.VISION_REGISTERS && visionDetail) {
          cursor[t] = Math.max(0, cursor[t] - 1);
        }
      }
      case F3 -> {
        if (table == Table.VISION_REGISTERS && visionDetail) {
          cursor[t] = Math.min(table.size - 1, cursor[t] + 1);
        }
        if (table == Table.POSITION_REGISTERS) {
          if (!p.shift()) {
            p.message("RECORD: hold SHIFT and press F3");
            return;
          }
          int n = index();
          Position now = regs.position(n) instanceof Position.Joint ? p.control().currentJoints()
              : p.control().currentPose(p.control().activeFrame(FrameKind.USER), p.control().activeFrame(FrameKind.TOOL));
          regs.setPosition(n, now);
          p.message("PR[" + n + "] recorded");
        }
      }
      case F4, F5 -> {
        int n = index();
        if (table == Table.VISION_REGISTERS && k == Key.F4) {
          visionDetail = !visionDetail;
          return;
        }
        if (table == Table.FLAGS) {
          regs.setBit(IoKind.F, n, k == Key.F4);
        } else if (table == Table.POSITION_REGISTERS && k == Key.F4) {
          p.confirm("Clear PR[" + n + "]?", () -> {
            regs.setPosition(n, Position.Cartesian.ZERO);
            p.message("PR[" + n + "] cleared");
          });
        }
      }
      case ENTER -> edit(p, null);
      default -> {
        if (k.keypadChar().isPresent()) {
          edit(p, String.valueOf(k.keypadChar().get()));
        }
      }
    }
  }

  @Override
  public void text(Pendant p, String s) {
    edit(p, s);
  }

  private void edit(Pendant p, String typed) {
    int n = index();
    if (table == Table.VISION_REGISTERS) {
      // Vision registers are written by VISION GET_OFFSET only; ENTER opens the detail page.
      visionDetail = true;
      return;
    }
    if (table == Table.FLAGS) {
      boolean on = !p.control().registers().bit(IoKind.F, n);
      p.control().registers().setBit(IoKind.F, n, on);
      return;
    }
    CommentTable ct = table == Table.REGISTERS ? CommentTable.R : CommentTable.PR;
    if (column == 0 || table == Table.POSITION_REGISTERS && typed != null
        && (typed.isEmpty() || !Character.isDigit(typed.charAt(0)))) {
      p.entryOrTyped(ct + "[" + n + "] comment:", typed, p.control().comment(ct, n), true, c -> {
        p.control().setComment(ct, n, c.trim());
        return Optional.empty();
      });
      return;
    }
    if (table == Table.POSITION_REGISTERS) {
      PositionScreen.openRegister(p, n);
      return;
    }
    p.entryOrTyped("R[" + n + "] value:", typed, "", false, s -> {
      String v = s.trim();
      double d;
      try {
        d = NumberEntry.finite("R[" + n + "]", v);
      } catch (ExprText.BadText e) {
        return Optional.of(e.getMessage());
      }
      if (v.matches("[+-]?\\d+") && Math.abs(d) <= Integer.MAX_VALUE) {
        p.control().registers().setInteger(n, (int) Math.round(d));
      } else {
        p.control().registers().setReal(n, d);
      }
      return Optional.empty();
    });
  }
}
