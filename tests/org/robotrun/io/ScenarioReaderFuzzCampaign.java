package org.robotrun.io;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/**
 * The long scenario-reader campaign: only with {@code ./mvnw verify -Pfuzz} (docs/fuzzing.md).
 * A random seed each run; jqwik prints the seed of a failure, and the failing input goes into
 * {@link HardenedFilesTest} as a regression test.
 */
class ScenarioReaderFuzzCampaign extends ScenarioReaderFuzzTest {
  @Override
  @Provide
  Arbitrary<byte[]> mutated() {
    return super.mutated();
  }

  @Property(tries = 50_000)
  void campaign(@ForAll("mutated") byte[] content) throws Exception {
    check(content);
  }
}
