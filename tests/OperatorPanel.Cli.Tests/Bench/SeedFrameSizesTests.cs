using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class SeedFrameSizesTests
{
    // Counted by hand from seed 000 Table 1 and the <MWxx?> listing (7 characters received, 9 sent):
    // '<' + letters + binary number(s) + '?' or '=' data + '>'.
    [Theory]
    [InlineData("IB0", 6, 7)]   // < I B 0 ? >          < I B 0 = z >
    [InlineData("QB1", 6, 7)]   // < Q B 1 ? >          < Q B 1 = z >
    [InlineData("MB11", 7, 8)]  // < M B x x ? >        < M B x x = z >
    [InlineData("VB124", 7, 8)]
    [InlineData("MW4", 7, 9)]   // < M W x x ? >        < M W x x = z z >    (the listing)
    [InlineData("VW432", 7, 9)]
    [InlineData("MD6", 7, 11)]  // < M D x x ? >        < M D x x = z z z z >
    [InlineData("VD104", 7, 11)]
    [InlineData("M10.3", 8, 9)] // < M x x . y ? >      < M x x . y = z >
    [InlineData("V440.5", 8, 9)]
    public void Sizes_TableOneCommands_MatchTheHandCount(string address, int request, int reply)
    {
        var parsed = PlcAddress.Parse(address);

        SeedFrameSizes.RequestChars(parsed).Should().Be(request);
        SeedFrameSizes.ReplyChars(parsed).Should().Be(reply);
    }
}
