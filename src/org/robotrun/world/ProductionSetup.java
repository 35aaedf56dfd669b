package org.robotrun.world;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.SortedMap;
import java.util.TreeMap;

/**
 * Production start from a PLC (issue 15): per robot (by name), the UOP setup of its controller
 * (UI/UO signals, remote/local, program selection by RSR, PNS or Style), reference positions with
 * their outputs, background logic programs, and a simple PLC sequence that drives the UOP inputs.
 * docs/scenario-format.md ("production") describes every field.
 *
 * @param robots the setup of each robot that has one, by robot name
 */
public record ProductionSetup(SortedMap<String, Robot> robots) {
  /** None: the scenario does not use this. */
  public static final ProductionSetup NONE = new ProductionSetup(new TreeMap<>());

  public ProductionSetup {
    robots = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(robots));
  }

  /** The setup of robot {@code name}, if the scenario gives one. */
  public Optional<Robot> of(String name) {
    return Optional.ofNullable(robots.get(name));
  }

  /** How a program is chosen from the PLC (MENU > SETUP > Prog Select on the controller). */
  public enum Selection {
    /** "Other": PROD_START/START run the program selected on the pendant. */
    OTHER,
    /** Robot Service Request: RSR1..8 each start their own program (RSRnnnn). */
    RSR,
    /** Program Number Select: PNS1..8 give a binary number, PNSTROBE reads it (PNSnnnn). */
    PNS,
    /** Style: PNS1..8 give a style number, PROD_START runs the style table's program. */
    STYLE
  }

  /**
   * One robot's production setup.
   *
   * @param uopEnabled "Enable UI signals" (system config): when false the UI inputs are ignored
   * @param remote the Remote/Local setup is Remote (a PLC may start programs)
   * @param selection the program selection method
   * @param pnsBase base number: PNS number n selects PNS(base+n), four digits
   * @param rsrBase base number: RSR i with registered number r starts RSR(base+r)
   * @param rsrNumbers registered numbers of RSR1..8 (index 0 = RSR1; 0 = that RSR disabled)
   * @param styles style number → program name
   * @param ackPulseSec width of the ACK1..8 and SNACK pulses
   * @param startForContinueOnly START (UI[6]) only resumes a paused program
   * @param cstopiAborts $SHELL_CFG.$USE_ABORT: CSTOPI aborts the running programs (false: it only
   *     clears the RSR queue and the program runs to its end)
   * @param homeProgram the macro UI[7] HOME runs, if any
   * @param referencePositions reference positions 1..10
   * @param backgroundLogic programs run by BG Logic, in slot order
   * @param bgScanSec how often BG logic runs each program from start to end
   * @param plc the PLC sequence driving this robot's UOP inputs (empty: none; the PLC panel drives them by hand)
   * @param startFromPlc {@code robotrun run} starts the cell through the PLC, not by SHIFT+FWD
   */
  public record Robot(boolean uopEnabled, boolean remote, Selection selection, int pnsBase, int rsrBase,
      List<Integer> rsrNumbers, SortedMap<Integer, String> styles, double ackPulseSec, boolean startForContinueOnly,
      boolean cstopiAborts, Optional<String> homeProgram, List<ReferencePosition> referencePositions,
      List<String> backgroundLogic, double bgScanSec, List<PlcStep> plc, boolean startFromPlc) {
    public Robot {
      Objects.requireNonNull(selection, "selection");
      rsrNumbers = List.copyOf(rsrNumbers);
      styles = java.util.Collections.unmodifiableSortedMap(new TreeMap<>(styles));
      Objects.requireNonNull(homeProgram, "homeProgram");
      referencePositions = List.copyOf(referencePositions);
      backgroundLogic = List.copyOf(backgroundLogic);
      plc = List.copyOf(plc);
      if (rsrNumbers.size() != 8) {
        throw new IllegalArgumentException("rsrNumbers: expected 8 entries (RSR1..8), got " + rsrNumbers.size());
      }
    }

    /** The controller's defaults: UOP on, remote, selection "Other", nothing else configured. */
    public static Robot defaults() {
      return new Robot(true, true, Selection.OTHER, 0, 0, List.of(0, 0, 0, 0, 0, 0, 0, 0), new TreeMap<>(), 0.2,
          false, false, Optional.empty(), List.of(), List.of(), 0.008, List.of(), false);
    }
  }

  /**
   * A reference position (MENU > SETUP > Ref Position): while every joint is within tolerance of
   * its value, the output is ON. Reference position 1 also drives UO[7] ATPERCH.
   *
   * @param number 1..10
   * @param comment shown on the setup screen
   * @param jointsDeg J1..J6 (pendant degrees)
   * @param toleranceDeg ± tolerance per joint
   * @param output the signal it drives ("DO[5]"), if any
   */
  public record ReferencePosition(int number, String comment, List<Double> jointsDeg, List<Double> toleranceDeg,
      Optional<Signal> output) {
    public ReferencePosition {
      Objects.requireNonNull(comment, "comment");
      jointsDeg = List.copyOf(jointsDeg);
      toleranceDeg = List.copyOf(toleranceDeg);
      Objects.requireNonNull(output, "output");
    }
  }

  /** A signal of this robot: kind ("DO", "UI" ...) and index. */
  public record Signal(String kind, int index) {
    public Signal {
      Objects.requireNonNull(kind, "kind");
    }

    @Override
    public String toString() {
      return kind + "[" + index + "]";
    }
  }

  /**
   * One step of a PLC sequence (a step chain, as a PLC's sequencer runs it): wait for a signal
   * (if any), then wait {@code delaySec}, then set the signals. The sequence runs once, from the
   * first step to the last, then stays on its last step.
   *
   * @param waitFor the signal to wait for, and the state it must have
   * @param delaySec seconds to wait after the condition holds
   * @param set the signals to set, in order (UI[] and DI[] inputs of this robot)
   * @param note what the step does, for the PLC panel
   */
  public record PlcStep(Optional<Map.Entry<Signal, Boolean>> waitFor, double delaySec, Map<Signal, Boolean> set,
      String note) {
    public PlcStep {
      Objects.requireNonNull(waitFor, "waitFor");
      set = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(set));
      Objects.requireNonNull(note, "note");
    }
  }
}
