// String built-ins: printf (per active point), format conversions, concat, match.

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

TEST(StringBuiltins, FormatConversions) {
    TestCall call(1);
    call.String("f=%f g=%.2f d=%d p=%p c=%c s=%s %% m0=%.0m");
    call.Float(1.5f).Float(2.345f).Float(7.9f);
    call.Uniform(TypeFromCode("p"), {1, 2, 3}).Uniform(TypeFromCode("c"), {0.5f, 0.25f, 1});
    call.String("hi");
    std::vector<float> identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    call.Uniform(TypeFromCode("m"), identity).StringResult();
    call.Run(FindKernel("format", "s", "s*"));
    EXPECT_EQ(call.StringOut(),
              "f=1.500000 g=2.35 d=7 p=1.000000 2.000000 3.000000 c=0.500000 0.250000 1.000000 "
              "s=hi % m0=1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1");
}

TEST(StringBuiltins, PrintfPrintsEachActivePointOnce) {
    const BuiltinInfo* row = FindRow("printf", "x", "s*");
    ASSERT_NE(row, nullptr);
    EXPECT_TRUE(row->flags & kHasSideEffects);
    FakeContext context(3);
    TestCall call(3);
    call.String("x=%g\n").Varying(TypeFromCode("f"), {{1}, {2}, {3}}).Mask({1, 0, 1});
    call.Context(&context).Run(row->kernel);
    EXPECT_EQ(context.printed, (std::vector<std::string>{"x=1\n", "x=3\n"}));
    FakeContext uniformContext(3);
    TestCall uniform(3);
    uniform.String("once %s").String("!").Context(&uniformContext).Run(row->kernel);
    EXPECT_EQ(uniformContext.printed, (std::vector<std::string>{"once !"}));
}

TEST(StringBuiltins, ConcatAndMatch) {
    TestCall concat(1);
    concat.String("a").String("bc").String("").String("d").StringResult();
    concat.Run(FindKernel("concat", "s", "ssss"));
    EXPECT_EQ(concat.StringOut(), "abcd");
    auto match = [](const std::string& pattern, const std::string& subject) {
        FakeContext context(1);
        TestCall call(1);
        call.String(pattern).String(subject).Result(TypeFromCode("f"), false).Context(&context);
        call.Run(FindKernel("match", "f", "ss"));
        return call.R(0);
    };
    EXPECT_EQ(match("^pl.*c$", "plastic"), 1.0f);
    EXPECT_EQ(match("metal", "plastic"), 0.0f);
    EXPECT_EQ(match("[", "plastic"), 0.0f);  // malformed: warns, no match
}

}  // namespace
}  // namespace gonio::sl::testing
