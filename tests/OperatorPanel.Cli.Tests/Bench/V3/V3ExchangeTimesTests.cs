using OperatorPanel.Cli.Bench;
using OperatorPanel.Cli.Bench.V3;

namespace OperatorPanel.Cli.Tests.Bench.V3;

public sealed class V3ExchangeTimesTests
{
    private const double Byte = 1.0416667;
    private static readonly LineSetting Line = new(9600, "8N1", 10);

    [Fact]
    public void Of_CableFixedHandler_PartsAreTheWireTheHandlerTheFifoAndTheGap()
    {
        var model = new LinkTimeModel(Line, 0, 5, 5, null);
        var planned = new V3PlannedExchange("idle", new byte[8], 9);
        var handler = new HandlerCost(3, TimeSpan.FromMilliseconds(12), TimeSpan.FromMilliseconds(9 * Byte), "fixed");

        var exchange = V3ExchangeTimes.Of(model, 4, planned, handler, Timed(9, 12, 0), []);

        // 8 request bytes + 12 ms to the first reply byte + 9 reply bytes + 4 bytes FIFO timeout + 5 ms gap.
        exchange.Chars.Should().Be(17);
        exchange.TotalMs.Should().BeApproximately(((8 + 9 + 4) * Byte) + 12 + 5, 1e-3);
    }

    [Fact]
    public void Floor_ReferenceLine_SteadyAndIdleAtTheWireEndTimerFifoAndGap()
    {
        V3RefreshFrames.TryCreate(ReferenceLine.Create(), out var frames, out _).Should().BeTrue();
        var model = new LinkTimeModel(Line, 0, 5, 5, null);

        // Steady 8 + 85 bytes, idle 8 + 9: each + 4 ms end timer + 4 bytes FIFO timeout + 5 ms gap.
        V3ExchangeTimes.Floor(model, 4, frames.Steady).TotalMs.Should().BeApproximately(((93 + 4) * Byte) + 9, 0.01);
        V3ExchangeTimes.Floor(model, 4, frames.Idle).TotalMs.Should().BeApproximately(((17 + 4) * Byte) + 9, 0.01);
    }

    [Fact]
    public void Of_RadioReplyPausedLongerThanTheDropTime_ModuleDropsItAndSaysSo()
    {
        var model = new LinkTimeModel(Line, 0, 5, 20, RadioModuleTiming.Default);
        var planned = new V3PlannedExchange("idle", new byte[8], 9);
        var problems = new List<string>();
        var handler = new HandlerCost(3, TimeSpan.FromMilliseconds(10), TimeSpan.FromMilliseconds((9 * Byte) + 1000.5), "fixed");

        V3ExchangeTimes.Of(model, 4, planned, handler, Timed(9, 10, 1000.5), problems);

        problems.Should().ContainSingle().Which.Should().Contain("the PLC module dropped the reply");
    }

    [Fact]
    public void Of_RadioReplyPausedLessThanTheDropTime_ForwardedAtItsLastByte()
    {
        var model = new LinkTimeModel(Line, 0, 5, 20, RadioModuleTiming.Default);
        var planned = new V3PlannedExchange("idle", new byte[8], 9);
        var problems = new List<string>();
        var handler = new HandlerCost(3, TimeSpan.FromMilliseconds(10), TimeSpan.FromMilliseconds((9 * Byte) + 999.5), "fixed");

        var exchange = V3ExchangeTimes.Of(model, 4, planned, handler, Timed(9, 10, 999.5), problems);

        problems.Should().BeEmpty();
        exchange.Parts.Single(p => p.What.StartsWith("reply on the bus", StringComparison.Ordinal)).Ms.Should().BeApproximately((9 * Byte) + 999.5, 1e-3);
    }

    /// <summary>A reply of <paramref name="bytes"/> bytes ('&lt;', LEN, then '&gt;' bytes) starting at <paramref name="startMs"/>, one pause before its last 2 bytes.</summary>
    private static List<(byte Value, TimeSpan At)> Timed(int bytes, double startMs, double pauseMs) =>
        [.. Enumerable.Range(0, bytes).Select(i => (
            i == 0 ? (byte)'<' : i == 1 ? (byte)bytes : (byte)'>',
            TimeSpan.FromMilliseconds(startMs + ((i + 1) * Byte) + (i >= bytes - 2 ? pauseMs : 0))))];
}
