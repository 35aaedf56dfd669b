package org.robotrun.io;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/** The long STL campaign: only with {@code ./mvnw verify -Pfuzz} (docs/fuzzing.md); random seed. */
class StlReaderFuzzCampaign extends StlReaderFuzzTest {
  @Override
  @Provide
  Arbitrary<byte[]> meshes() {
    return super.meshes();
  }

  @Override
  @Provide
  Arbitrary<Double> scales() {
    return super.scales();
  }

  @Property(tries = 200_000)
  void campaign(@ForAll("meshes") byte[] bytes, @ForAll("scales") double scale) {
    check(bytes, scale);
  }
}
