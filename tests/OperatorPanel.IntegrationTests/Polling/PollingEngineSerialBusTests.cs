using System.Text;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// Several stations on one simulated RS-485 bus behind a real serial line (socat pty pair): each station answers only
/// for itself, a silent station goes offline while the others keep updating, and line noise does not stop polling.
/// </summary>
public sealed class PollingEngineSerialBusTests
{
    private static readonly string[] Watched = ["VW100", "MB0", "I0.3"];

    [Fact]
    public async Task Refresh_ThreeStationsOnOneBus_EachAnswersOnlyForItself()
    {
        ReferencePlc[] plcs = [SerialLineRig.Plc(2), SerialLineRig.Plc(3), SerialLineRig.Plc(4)];
        Array.ForEach(plcs, p => Load(p, 1000));
        await using var rig = await SerialLineRig.StartAsync(plcs, Watched);

        var result = await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        result.FramesSent.Should().Be(3);
        result.FramesFailed.Should().Be(0);
        var requests = plcs.Sum(p => rig.Bus.StatisticsFor(p.Config.Station).Requests);
        rig.Tap.Replies.Should().Be((int)requests, "one reply per request: no station answered another's request");
        foreach (var plc in plcs)
        {
            var station = plc.Config.Station.Address;
            rig.State(plc).Should().Be(StationState.Online);
            rig.Value(plc, "VW100").Raw.Should().Equal((byte)((1000 + station) >> 8), (byte)(1000 + station));
            rig.Value(plc, "MB0").Raw.Should().Equal((byte)station);
            rig.Value(plc, "I0.3").AsBit.Should().Be(station % 2 == 1);
        }
    }

    [Fact]
    public async Task Refresh_OneStationInStop_GoesOfflineWhileOthersKeepUpdatingAndReturns()
    {
        ReferencePlc[] plcs = [SerialLineRig.Plc(2), SerialLineRig.Plc(3), SerialLineRig.Plc(4)];
        var (first, silent, last) = (plcs[0], plcs[1], plcs[2]);
        Array.ForEach(plcs, p => Load(p, 1000));
        await using var rig = await SerialLineRig.StartAsync(plcs, Watched);
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        silent.Mode = OperatingMode.Stop;
        foreach (var round in new[] { 2000, 3000 })
        {
            Array.ForEach(plcs, p => Load(p, round));
            await rig.RefreshUntilAsync(_ => rig.State(silent) == StationState.Offline && Holds(rig, first, round) && Holds(rig, last, round));

            rig.State(silent).Should().Be(StationState.Offline);
            rig.Value(silent, "VW100").Quality.Should().Be(ValueQuality.Stale);
            rig.Value(silent, "VW100").Raw.Should().Equal(new byte[] { 0x03, 0xEB }, "the last good value, 1003, is kept");
            rig.State(first).Should().Be(StationState.Online);
            Holds(rig, first, round).Should().BeTrue($"station 2 keeps updating (round {round})");
            Holds(rig, last, round).Should().BeTrue($"station 4 keeps updating (round {round})");
        }

        silent.Mode = OperatingMode.Run;
        await rig.RefreshUntilAsync(_ => rig.State(silent) == StationState.Online && Holds(rig, silent, 3000));

        rig.State(silent).Should().Be(StationState.Online);
        Holds(rig, silent, 3000).Should().BeTrue("station 3 is read again once back in RUN");
    }

    [Fact]
    public async Task Refresh_GarbageOnTheLineBetweenReplies_EveryCycleStillReadsTheValues()
    {
        var plc = SerialLineRig.Plc(5);
        await using var rig = await SerialLineRig.StartAsync([plc], Watched);

        // Three kinds of noise in turn: stray bytes outside any frame, a frame start cut off by the real reply's '<',
        // and a complete frame that is not a valid reply (the PC drops it and repeats the request).
        rig.Tap.NoiseBeforeReply = n => (n % 3) switch
        {
            0 => [0x00, 0xFF, .. Encoding.ASCII.GetBytes("Z9\r\n")],
            1 => Encoding.ASCII.GetBytes("<05FF8"),
            _ => Encoding.ASCII.GetBytes("<0G1>xx"),
        };

        for (var cycle = 1; cycle <= 9; cycle++)
        {
            Load(plc, cycle * 111);
            await rig.RefreshUntilAsync(_ => Holds(rig, plc, cycle * 111));

            Holds(rig, plc, cycle * 111).Should().BeTrue($"cycle {cycle} reads the new value through the noise");
        }

        rig.Bus.StatisticsFor(plc.Config.Station).CorruptFrames.Should().BeGreaterThan(0, "the noise did reach the panel");
        rig.State(plc).Should().Be(StationState.Online);
    }

    /// <summary>The panel holds, as good values, what <see cref="Load"/> put in the PLC for <paramref name="value"/>.</summary>
    private static bool Holds(SerialLineRig rig, ReferencePlc plc, int value)
    {
        var station = plc.Config.Station.Address;
        var word = rig.Value(plc, "VW100");
        return word.Quality == ValueQuality.Good
            && word.Raw.SequenceEqual([(byte)((value + station) >> 8), (byte)(value + station)])
            && rig.Value(plc, "MB0").Raw.SequenceEqual([(byte)station]);
    }

    /// <summary>VW100 = base + station, MB0 = station, I0.3 = station is odd.</summary>
    private static void Load(ReferencePlc plc, int value)
    {
        var station = plc.Config.Station.Address;
        plc.Memory.WriteWord(ProtocolArea.V, 100, (ushort)(value + station));
        plc.Memory.M[0] = (byte)station;
        plc.Memory.SetBit(ProtocolArea.I, 0, 3, station % 2 == 1);
    }
}
