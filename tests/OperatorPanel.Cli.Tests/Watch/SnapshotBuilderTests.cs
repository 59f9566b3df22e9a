using System.Text.Json;
using OperatorPanel.Cli.Watch;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.TestKit;
using Serilog.Core;

namespace OperatorPanel.Cli.Tests.Watch;

/// <summary>
/// Watch's lamps never show unknown as known: a bit is lit or dark only on a good reading; the bits of a station that
/// stopped answering (stale) or was refused (bad) are '?', as a bit never read is, and JSON gives each bit its quality.
/// </summary>
public sealed class SnapshotBuilderTests
{
    private static readonly DateTimeOffset Read = new(2026, 11, 25, 5, 0, 0, TimeSpan.Zero);

    private static readonly IoSymbol[] Inputs =
    [
        new("EStopHealthy", PlcAddress.Parse("I0.0"), string.Empty),
        new("StartButton", PlcAddress.Parse("I0.1"), string.Empty),
        new("StopButton", PlcAddress.Parse("I0.2"), string.Empty),
        new("ResetButton", PlcAddress.Parse("I0.3"), string.Empty),
        new("AutoMode", PlcAddress.Parse("I0.4"), string.Empty),
        new("InfeedBottle", PlcAddress.Parse("I0.5"), string.Empty),
    ];

    [Fact]
    public void Lamps_GoodStaleBadAndMissingReadings_OnlyGoodOnesAreLitOrDark()
    {
        var readings = new Dictionary<string, PolledValue>
        {
            ["I0.0"] = PolledValue.Good([1], Read),
            ["I0.1"] = PolledValue.Good([0], Read),
            ["I0.2"] = Stale(true),
            ["I0.3"] = Stale(false),
            ["I0.4"] = new([], Read, ValueQuality.Bad, "refused"),
        };

        var lamps = SnapshotBuilder.Lamps(Inputs, a => readings.TryGetValue(a.ToString(), out var v) ? v : null);

        lamps.Should().ContainSingle().Which.Lamps.Should().Be("●○????··", "I0.2-I0.3 are stale, I0.4 bad, I0.5 has no reading");
        lamps[0].Bits.Select(b => (b.Address, b.On, b.Quality)).Should().Equal(
            ("I0.0", true, "good"), ("I0.1", false, "good"), ("I0.2", true, "stale"), ("I0.3", false, "stale"), ("I0.4", (bool?)null, "bad"), ("I0.5", null, "bad"));
    }

    [Fact]
    public void Render_OfflineStationWhoseBitsWentStale_ShowsItsLampsUnknown()
    {
        var text = SnapshotRenderer.Render(Snapshot(OfflineWithStaleInputs()));

        text.Should().Contain("    IB0   ??????··  I0.0 EStopHealthy  I0.1 StartButton", "the last values (on, off, ...) are not the PLC's now")
            .And.Contain("  inputs (bit 0 first; ● on, ○ off, ? unknown: not read, stale or bad)");
    }

    [Fact]
    public void Json_OfflineStationWhoseBitsWentStale_GivesEachBitItsQualityBesideItsLastReading()
    {
        using var output = new StringWriter();
        var cli = new CliContext(output, TextWriter.Null, Json: true, Logger.None);

        new LiveOutput(cli, everyCycle: true, new ManualTimeProvider()).CycleCompleted(() => Snapshot(OfflineWithStaleInputs()));

        using var json = JsonDocument.Parse(output.ToString());
        var inputs = json.RootElement.GetProperty("stations")[0].GetProperty("inputs")[0];
        inputs.GetProperty("lamps").GetString().Should().Be("??????··");
        var bits = inputs.GetProperty("bits").EnumerateArray().ToList();
        bits.Select(b => b.GetProperty("quality").GetString()).Should().AllBe("stale").And.HaveCount(6);
        bits[0].GetProperty("on").GetBoolean().Should().BeTrue("the last reading is kept, as a stale tag keeps its value");
        bits[1].GetProperty("on").GetBoolean().Should().BeFalse();
    }

    private static PolledValue Stale(bool on) => new([on ? (byte)1 : (byte)0], Read, ValueQuality.Stale, "station 2: no answer");

    private static StationSnapshot OfflineWithStaleInputs()
    {
        var stale = Inputs.ToDictionary(s => s.Address, s => Stale(s.Address.Bit % 2 == 0));
        return new StationSnapshot(
            "Filler", 2, "CPU 224", "COM3 9600 8N1", "offline", "station 2: serial port COM3: read failed: the device vanished (unplugged?) - reconnecting", null, null,
            new LinkView(40, 38, 0, 2, 120.0), SnapshotBuilder.Lamps(Inputs, a => stale.GetValueOrDefault(a)), [], [], []);
    }

    private static WatchSnapshot Snapshot(StationSnapshot station) =>
        new("Line", "continuous, at least 100 ms apart", 7, Read, [station]);
}
