package org.robotrun.program;

import java.util.Objects;

/**
 * One part a vision process found, as a vision register VR[i] holds it after
 * {@code VISION GET_OFFSET} (iRVision's fixed frame offset).
 *
 * @param process the vision process that found it
 * @param modelId the model ID of the locator that found it (VR[i].MODELID)
 * @param found the found position of the part in the process's user frame (VR[i].FOUND_POS[1])
 * @param offset the fixed frame offset O with found = O · reference, in that user frame (VR[i].OFFSET)
 * @param userFrame the process's application user frame number, 0..10
 * @param score the match score, 0..100 (VR[i].MES[1])
 */
public record VisionResult(String process, int modelId, Position.Cartesian found, Position.Cartesian offset,
    int userFrame, double score) {
  public VisionResult {
    Objects.requireNonNull(process, "process");
    Objects.requireNonNull(found, "found");
    Objects.requireNonNull(offset, "offset");
  }
}
