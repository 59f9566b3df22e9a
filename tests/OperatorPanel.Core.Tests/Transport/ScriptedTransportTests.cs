using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Transport;

/// <summary>The TestKit fake the link tests rely on: scripts must fail loudly and echo captures exactly.</summary>
public sealed class ScriptedTransportTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromMilliseconds(300);

    [Fact]
    public async Task Read_AfterMatchingRequest_ReturnsResponseWithEchoedCaptureAndBcc()
    {
        var transport = new ScriptedTransport("""
            // IDENTIFY station 1, whatever SEQ the PC chose
            > "<01" {seq} "01" ?? ?? ">"
            < "<01" {seq} "8100" {bcc} ">"
            """);

        await transport.WriteAsync(Hex.Ascii("<0142017F>"), default);
        var buffer = new byte[32];
        var count = await transport.ReadAsync(buffer, Timeout, default);

        // BCC = '0'^'1'^'4'^'2'^'8'^'1'^'0'^'0' = 16#0E
        buffer[..count].Should().Equal(Hex.Ascii("<014281000E>"));
        transport.AssertComplete();
    }

    [Fact]
    public async Task Write_DiffersFromScript_ThrowsAndAssertCompleteFails()
    {
        var transport = new ScriptedTransport("""> 3C 30 31 3E  // <01>""");

        await transport.Invoking(t => t.WriteAsync(Hex.Parse("3C 30 32 3E"), default))
            .Should().ThrowAsync<ScriptMismatchException>().WithMessage("*line 1*byte 2 is 32, expected 31*");
        transport.Invoking(t => t.AssertComplete()).Should().Throw<ScriptMismatchException>();
    }

    [Fact]
    public async Task Read_NoResponseStep_ReturnsZeroAndAdvancesClockByTimeout()
    {
        var clock = new ManualTimeProvider();
        var start = clock.GetUtcNow();
        var transport = new ScriptedTransport("""
            > "<A>"
            < no response
            """, clock);

        await transport.WriteAsync(Hex.Ascii("<A>"), default);
        var count = await transport.ReadAsync(new byte[8], Timeout, default);

        count.Should().Be(0);
        (clock.GetUtcNow() - start).Should().Be(Timeout);
    }

    [Fact]
    public async Task Read_ResponseInTwoLines_ComesAsTwoChunks()
    {
        var transport = new ScriptedTransport("""
            > 01
            < "<01"
            < "23>"
            """);
        await transport.WriteAsync(Hex.Parse("01"), default);
        var buffer = new byte[8];

        var first = await transport.ReadAsync(buffer, Timeout, default);
        var second = await transport.ReadAsync(buffer.AsMemory(first), Timeout, default);

        (first, second).Should().Be((3, 3));
        buffer[..6].Should().Equal(Hex.Ascii("<0123>"));
    }

    [Fact]
    public void AssertComplete_RequestNeverWritten_Fails()
    {
        var transport = new ScriptedTransport("> 01\n> 02");

        transport.Invoking(t => t.AssertComplete()).Should().Throw<ScriptMismatchException>().WithMessage("*line 1*");
    }

    [Theory]
    [InlineData("3C 30 31", new byte[] { 0x3C, 0x30, 0x31 })]
    [InlineData("3c30 // start and '0'\n31", new byte[] { 0x3C, 0x30, 0x31 })]
    [InlineData("", new byte[0])]
    public void HexParse_SpacedOrCommented_GivesBytes(string text, byte[] expected)
    {
        Hex.Parse(text).Should().Equal(expected);
    }

    [Fact]
    public void HexFormat_Bytes_AreSpacedUppercasePairs()
    {
        Hex.Format(new byte[] { 0x3C, 0x0A, 0xFF }).Should().Be("3C 0A FF");
    }
}
