package org.robotrun.grade;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/** The long hand-in campaign: only with {@code ./mvnw verify -Pfuzz} (docs/fuzzing.md), a random seed each run. */
class HandInFuzzCampaign extends HandInFuzzTest {
  @Override
  @Provide
  Arbitrary<byte[]> zips() {
    return super.zips();
  }

  @Property(tries = 20_000)
  void campaign(@ForAll("zips") byte[] zip) throws Exception {
    check(zip);
  }
}
