using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary>The time model on fixed inputs, counted by hand (9600 8N1: 1.041667 ms a character).</summary>
public sealed class LinkTimeModelTests
{
    private const double Character = 1.0416667;
    private static readonly LineSetting Line9600 = new(9600, "8N1", 10);
    private static readonly HandlerCost FourScans = new(4, TimeSpan.FromMilliseconds(30), TimeSpan.FromMilliseconds((20 * Character) + 3), "fixed");

    [Fact]
    public void Exchange_Cable_RequestUntilTheFirstReplyCharacterTheReplyWithItsPausesFifoTimeoutAndGap()
    {
        var model = new LinkTimeModel(Line9600, ReplyDelayMs: 5, ProgramScanMs: 5, LinkGapMs: 5, Radio: null);

        var exchange = model.Exchange("READ CHANGES", 16, 20, FourScans);

        exchange.Parts.Select(p => p.Ms).Should().Equal(
            [16 * Character, 30, (20 * Character) + 3, 4 * Character, 5],
            (a, b) => Math.Abs(a - b) < 1e-4);
        exchange.Parts[2].What.Should().Be("reply on the bus, 3.00 ms of it pauses while the handler computes its check");
        exchange.TotalMs.Should().BeApproximately((40 * Character) + 38, 1e-4);
        exchange.Chars.Should().Be(36);
    }

    [Fact]
    public void Exchange_FirstReplyCharacterSoonerThanTheCableTurnaround_WaitsForTheCable()
    {
        // 9600 baud: 4 ms turnaround; the PLC would start the reply 1.5 ms after the request's '>'.
        var model = new LinkTimeModel(Line9600, ReplyDelayMs: 1, ProgramScanMs: 0, LinkGapMs: 5, Radio: null);

        var exchange = model.Exchange("x", 10, 10, new HandlerCost(1, TimeSpan.FromMilliseconds(1.5), TimeSpan.FromMilliseconds(10 * Character), "fixed"));

        exchange.Parts.Single(p => p.What.StartsWith("until the first reply character", StringComparison.Ordinal)).Ms.Should().Be(4);
    }

    [Fact]
    public void Exchange_Radio_BothUartsTheAirBothWaysUsbAndTheLatencyTimer()
    {
        var model = new LinkTimeModel(Line9600, ReplyDelayMs: 5, ProgramScanMs: 5, LinkGapMs: 20, Radio: RadioModuleTiming.Default);

        var exchange = model.Exchange("READ CHANGES", 16, 20, FourScans);

        // Air: 0.799 ms + (9 + 16) bytes x 8 bits / 38.4 kBaud = 6.0073 ms; reply 0.799 + 29 x 8 / 38.4 = 6.8407 ms. The
        // PLC-side module forwards the reply once its '>' is in: after the reply's whole time on the bus, pauses included.
        exchange.Parts.Select(p => p.Ms).Should().Equal(
            [1, 16 * Character, 6.0073, 16 * Character, 30, (20 * Character) + 3, 6.8407, 20 * Character, 16, 20],
            (a, b) => Math.Abs(a - b) < 1e-4);
    }

    [Fact]
    public void Pauses_ReplyLongerOnTheBusThanItsCharacters_TheDifference()
    {
        FourScans.Pauses(20, TimeSpan.FromMilliseconds(Character)).TotalMilliseconds.Should().BeApproximately(3, 0.01);
        FourScans.Pauses(30, TimeSpan.FromMilliseconds(Character)).Should().Be(TimeSpan.Zero);
    }

    [Theory]
    [InlineData(1200, 25.0)]   // 3 characters of 8.333 ms
    [InlineData(9600, 5.0)]    // 3 x 1.04 ms < 5 ms
    [InlineData(38400, 5.0)]
    public void GapMs_ShortLinkGap_RaisedToFiveMsAndThreeCharacters(int baud, double expected)
    {
        var model = new LinkTimeModel(new LineSetting(baud, "8N1", 10), 5, 5, LinkGapMs: 0, Radio: null);

        model.GapMs.Should().BeApproximately(expected, 1e-9);
    }

    [Fact]
    public void GapMs_LongerLinkGap_Kept()
    {
        new LinkTimeModel(Line9600, 5, 5, LinkGapMs: 20, Radio: null).GapMs.Should().Be(20);
    }

    [Theory]
    [InlineData(9600, 4)]
    [InlineData(19200, 2)]
    [InlineData(14400, 4)]  // between rows: the slower row's larger figure
    [InlineData(115200, 0.25)]
    [InlineData(300, 28)]
    public void TurnaroundMs_Baud_TheTableRowOrTheSlowerOne(int baud, double expected)
    {
        CableTiming.TurnaroundMs(baud).Should().Be(expected);
    }
}
