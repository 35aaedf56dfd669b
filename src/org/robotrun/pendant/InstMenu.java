package org.robotrun.pendant;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.function.Supplier;
import org.robotrun.program.SystemVariables;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;

/**
 * The EDIT screen's [INST] menu: categories as on the controller, each a list of statement
 * templates. A template is inserted with default numbers ({@code R[1]=0}); the operator then
 * edits its fields. Together with POINT (motion) and [EDCMD] (blank lines, {@code //}) this
 * reaches every statement of TP-LANGUAGE.md.
 */
final class InstMenu {
  private InstMenu() {}

  /** One menu entry: its label and the statement(s) it inserts. */
  record Template(String label, Supplier<List<Instruction>> lines) {
    Template {
      Objects.requireNonNull(label, "label");
      Objects.requireNonNull(lines, "lines");
    }

    static Template of(String label, Instruction... lines) {
      List<Instruction> l = List.of(lines);
      return new Template(label, () -> l);
    }
  }

  /** A category of the menu. */
  record Category(String title, List<Template> templates) {
    Category {
      templates = List.copyOf(templates);
    }
  }

  private static Expr r(int i) {
    return new Expr.Register(Item.of(i));
  }

  private static Expr cmp(Expr.BinaryOp op, Expr a, Expr b) {
    return new Expr.Binary(op, a, b);
  }

  private static Expr ioOn(IoKind k, int i) {
    return cmp(Expr.BinaryOp.EQ, new Expr.Io(k, Item.of(i)), new Expr.OnOff(true));
  }

  /** The vision process a new VISION line names until the operator types another. */
  private static final Instruction.VisionProcess VISION_PROCESS = new Instruction.VisionProcessName("FIND");

  static final List<Category> CATEGORIES = List.of(
      new Category("Registers", List.of(
          Template.of("R[ ]=...", new Instruction.AssignRegister(Item.of(1), new Expr.IntConst(0))),
          Template.of("R[ ]=R[ ]+R[ ]", new Instruction.AssignRegister(Item.of(1), cmp(Expr.BinaryOp.ADD, r(1), new Expr.IntConst(1)))),
          Template.of("R[ ]=(...)", new Instruction.AssignRegister(Item.of(1),
              new Expr.Group(cmp(Expr.BinaryOp.MUL, r(2), new Expr.IntConst(2))))),
          Template.of("PR[ ]=PR[ ]", new Instruction.AssignPosReg(Item.of(1), new Instruction.FromPosReg(Item.of(2)))),
          Template.of("PR[ ]=P[ ]", new Instruction.AssignPosReg(Item.of(1), new Instruction.FromLocal(1, ""))),
          Template.of("PR[ ]=LPOS", new Instruction.AssignPosReg(Item.of(1), new Instruction.CurrentLpos())),
          Template.of("PR[ ]=JPOS", new Instruction.AssignPosReg(Item.of(1), new Instruction.CurrentJpos())),
          Template.of("PR[ ]=UFRAME[ ]", new Instruction.AssignPosReg(Item.of(1), new Instruction.FromFrame(FrameKind.USER, Index.of(1)))),
          Template.of("PR[ ]=UTOOL[ ]", new Instruction.AssignPosReg(Item.of(1), new Instruction.FromFrame(FrameKind.TOOL, Index.of(1)))),
          Template.of("PR[ ]=PR[ ]+PR[ ]", new Instruction.AssignPosReg(Item.of(1), new Instruction.PosArithmetic(Item.of(2), true, Item.of(3)))),
          Template.of("PR[ ]=PR[ ]-PR[ ]", new Instruction.AssignPosReg(Item.of(1), new Instruction.PosArithmetic(Item.of(2), false, Item.of(3)))),
          Template.of("PR[i,j]=...", new Instruction.AssignPosElement(Item.of(1), 1, new Expr.IntConst(0))),
          Template.of("SR[ ]=...", new Instruction.AssignString(Item.of(1), new Expr.StringReg(Item.of(2)))),
          Template.of("R[ ]=STRLEN SR[ ]", new Instruction.AssignRegister(Item.of(1),
              new Expr.StringFunc(Expr.StringFn.STRLEN, java.util.List.of(new Expr.StringReg(Item.of(1)))))))),
      new Category("I/O", List.of(
          Template.of("DO[ ]=ON/OFF", new Instruction.SetIo(IoKind.DO, Item.of(1), new Expr.OnOff(true))),
          Template.of("DO[ ]=PULSE", new Instruction.Pulse(IoKind.DO, Item.of(1), OptionalDouble.empty())),
          Template.of("DO[ ]=PULSE,t sec", new Instruction.Pulse(IoKind.DO, Item.of(1), OptionalDouble.of(0.5))),
          Template.of("DO[ ]=R[ ]", new Instruction.SetIo(IoKind.DO, Item.of(1), r(1))),
          Template.of("RO[ ]=ON/OFF", new Instruction.SetIo(IoKind.RO, Item.of(1), new Expr.OnOff(true))),
          Template.of("RO[ ]=PULSE,t sec", new Instruction.Pulse(IoKind.RO, Item.of(1), OptionalDouble.of(0.5))),
          Template.of("GO[ ]=n", new Instruction.SetIo(IoKind.GO, Item.of(1), new Expr.IntConst(0))),
          Template.of("F[ ]=(...)", new Instruction.SetIo(IoKind.F, Item.of(1), new Expr.Group(ioOn(IoKind.DI, 1)))),
          Template.of("R[ ]=DI[ ]", new Instruction.AssignRegister(Item.of(1), new Expr.Io(IoKind.DI, Item.of(1)))))),
      new Category("IF/SELECT", List.of(
          Template.of("IF ...,JMP LBL[ ]", new Instruction.If(cmp(Expr.BinaryOp.GT, r(1), new Expr.IntConst(0)),
              new Instruction.Jump(LabelRef.of(1)))),
          Template.of("IF ...,CALL", new Instruction.If(ioOn(IoKind.DI, 1), new Instruction.Call("MAIN", List.of()))),
          Template.of("IF ...,R[ ]=(...)", new Instruction.IfAction(cmp(Expr.BinaryOp.GT, r(1), new Expr.IntConst(0)),
              new Instruction.AssignRegister(Item.of(2), new Expr.Group(new Expr.IntConst(1))))),
          Template.of("IF ...,DO[ ]=(...)", new Instruction.IfAction(ioOn(IoKind.DI, 1),
              new Instruction.SetIo(IoKind.DO, Item.of(1), new Expr.Group(new Expr.OnOff(true))))),
          new Template("IF (...) THEN / ELSE / ENDIF", () -> List.of(
              new Instruction.IfThen(new Expr.Group(cmp(Expr.BinaryOp.GT, r(1), new Expr.IntConst(0)))),
              new Instruction.Else(), new Instruction.EndIf())),
          Template.of("IF (...) THEN", new Instruction.IfThen(new Expr.Group(cmp(Expr.BinaryOp.GT, r(1), new Expr.IntConst(0))))),
          Template.of("ELSE", new Instruction.Else()),
          Template.of("ENDIF", new Instruction.EndIf()),
          new Template("SELECT R[ ]=...,JMP / =... / ELSE", () -> List.of(
              new Instruction.Select(Item.of(1), new Expr.IntConst(1), new Instruction.Jump(LabelRef.of(1))),
              new Instruction.SelectCase(new Expr.IntConst(2), new Instruction.Jump(LabelRef.of(2))),
              new Instruction.SelectElse(new Instruction.Jump(LabelRef.of(3))))),
          Template.of("SELECT R[ ]=...,JMP LBL[ ]", new Instruction.Select(Item.of(1), new Expr.IntConst(1),
              new Instruction.Jump(LabelRef.of(1)))),
          Template.of("=...,JMP LBL[ ] (case)", new Instruction.SelectCase(new Expr.IntConst(2), new Instruction.Jump(LabelRef.of(2)))),
          Template.of("ELSE,JMP LBL[ ] (select)", new Instruction.SelectElse(new Instruction.Jump(LabelRef.of(3)))))),
      new Category("WAIT", List.of(
          Template.of("WAIT t(sec)", new Instruction.WaitTime(new Expr.RealConst(1.0))),
          Template.of("WAIT R[ ]", new Instruction.WaitTime(r(1))),
          Template.of("WAIT cond", new Instruction.WaitCondition(ioOn(IoKind.DI, 1), Optional.empty())),
          Template.of("WAIT cond TIMEOUT,LBL[ ]", new Instruction.WaitCondition(ioOn(IoKind.DI, 1), Optional.of(LabelRef.of(1)))))),
      new Category("JMP/LBL", List.of(
          Template.of("LBL[ ]", new Instruction.Label(1, "")),
          Template.of("JMP LBL[ ]", new Instruction.Jump(LabelRef.of(1))),
          Template.of("JMP LBL[R[ ]]", new Instruction.Jump(new LabelRef(Index.viaRegister(1), ""))))),
      new Category("CALL", List.of(
          Template.of("CALL program", new Instruction.Call("MAIN", List.of())),
          Template.of("CALL program(args)", new Instruction.Call("MAIN", List.of(new Expr.IntConst(1)))))),
      new Category("FOR/ENDFOR", List.of(
          new Template("FOR R[ ]=1 TO 3 / ENDFOR", () -> List.of(
              new Instruction.For(Item.of(1), new Expr.IntConst(1), false, new Expr.IntConst(3)), new Instruction.EndFor())),
          Template.of("FOR R[ ]=... DOWNTO ...", new Instruction.For(Item.of(1), new Expr.IntConst(3), true, new Expr.IntConst(1))),
          Template.of("ENDFOR", new Instruction.EndFor()))),
      new Category("Program control", List.of(
          Template.of("END", new Instruction.End()),
          Template.of("PAUSE", new Instruction.Pause()),
          Template.of("ABORT", new Instruction.Abort()))),
      new Category("Frames/payload", List.of(
          Template.of("UFRAME_NUM=...", new Instruction.SelectFrame(FrameKind.USER, Index.of(1))),
          Template.of("UTOOL_NUM=...", new Instruction.SelectFrame(FrameKind.TOOL, Index.of(1))),
          Template.of("UFRAME[ ]=PR[ ]", new Instruction.SetFrame(FrameKind.USER, Index.of(1), Item.of(1))),
          Template.of("UTOOL[ ]=PR[ ]", new Instruction.SetFrame(FrameKind.TOOL, Index.of(1), Item.of(1))),
          Template.of("PAYLOAD[ ]", new Instruction.Payload(Index.of(1))))),
      new Category("Miscellaneous", List.of(
          Template.of("! comment", new Instruction.Comment("")),
          Template.of("MESSAGE[...]", new Instruction.Message("")),
          Template.of("TIMER[ ]=START", new Instruction.TimerSet(Item.of(1), Instruction.TimerAction.START)),
          Template.of("TIMER[ ]=STOP", new Instruction.TimerSet(Item.of(1), Instruction.TimerAction.STOP)),
          Template.of("TIMER[ ]=RESET", new Instruction.TimerSet(Item.of(1), Instruction.TimerAction.RESET)),
          Template.of("UALM[ ]", new Instruction.UserAlarm(Index.of(1))),
          Template.of("OVERRIDE=...%", new Instruction.SetOverride(new Expr.IntConst(100))),
          Template.of("(blank line)", new Instruction.Blank()),
          Template.of("//commented-out line", new Instruction.CommentedOut("")),
          Template.of("$WAITTMOUT=... (parameter name)", new Instruction.SetSysVar(SystemVariables.WAITTMOUT, new Expr.IntConst(3000))),
          Template.of("$MCR.$GENOVERRIDE=... (parameter name)",
              new Instruction.SetSysVar(SystemVariables.GENOVERRIDE, new Expr.IntConst(100))),
          Template.of("SKIP CONDITION ...", new Instruction.SkipCondition(
              new Expr.Binary(Expr.BinaryOp.EQ, new Expr.Io(IoKind.DI, Item.of(1)), new Expr.OnOff(true)))),
          Template.of("OFFSET CONDITION PR[ ]", new Instruction.OffsetCondition(Item.of(1))),
          Template.of("macro (a program run by its name)", new Instruction.MacroCall("MAIN")),
          Template.of("MONITOR ...", new Instruction.Monitor("MAIN", false)),
          Template.of("MONITOR END ...", new Instruction.Monitor("MAIN", true)),
          Template.of("WHEN ...,CALL ... (condition program)", new Instruction.When(
              new Expr.Binary(Expr.BinaryOp.EQ, new Expr.Io(IoKind.DI, Item.of(1)), new Expr.OnOff(true)),
              new Instruction.Call("MAIN", List.of()))))),
      new Category("Multiple control", List.of(
          Template.of("RUN program", new Instruction.Run("MAIN", List.of())))),
      // iRVision (docs/vision.md): the process name is edited on the line
      new Category("Vision", List.of(
          Template.of("VISION RUN_FIND ...", new Instruction.VisionRunFind(VISION_PROCESS)),
          Template.of("VISION GET_OFFSET ... VR[ ] JMP,LBL[ ]", new Instruction.VisionGetOffset(VISION_PROCESS, Item.of(1),
              LabelRef.of(1))),
          Template.of("VISION GET_NFOUND ... R[ ]", new Instruction.VisionGetNFound(VISION_PROCESS, Item.of(1))),
          Template.of("R[ ]=VR[ ].MODELID", new Instruction.AssignFromVr(Item.of(1), Item.of(1),
              Instruction.VisionField.MODELID, 0)),
          Template.of("PR[ ]=VR[ ].OFFSET", new Instruction.AssignPosReg(Item.of(1),
              new Instruction.FromVisionRegister(Item.of(1), false))))));

  /** Motion options the [CHOICE] key adds to a motion line. */
  static final List<String> MOTION_OPTIONS = List.of("Offset", "Offset,PR[ ]", "Tool_Offset,PR[ ]", "ACC 100",
      "Skip,LBL[ ]", "Wjnt", "INC", "VOFFSET,VR[ ]");

  static org.robotrun.program.Motion.Option motionOption(int i) {
    return switch (i) {
      case 0 -> new org.robotrun.program.Motion.Offset();
      case 1 -> new org.robotrun.program.Motion.OffsetPr(Item.of(1));
      case 2 -> new org.robotrun.program.Motion.ToolOffsetPr(Item.of(1));
      case 3 -> new org.robotrun.program.Motion.Acc(100);
      case 4 -> new org.robotrun.program.Motion.Skip(LabelRef.of(1));
      case 5 -> new org.robotrun.program.Motion.Wjnt();
      case 6 -> new org.robotrun.program.Motion.Inc();
      default -> new org.robotrun.program.Motion.VisionOffset(Item.of(1));
    };
  }
}
