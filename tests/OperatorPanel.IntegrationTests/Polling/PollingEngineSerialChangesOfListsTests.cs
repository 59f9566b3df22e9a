using System.Globalization;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// 09 READ CHANGES OF LISTS end to end over a socat pty against the reference model, whose IDENTIFY has FEATURES bit 2:
/// a station with two stored lists (26 one-byte items VB0, VB10 .. VB250), frames counted from the characters the PLC
/// end received and sent.
/// </summary>
public sealed partial class PollingEngineSerialChangesOfListsTests
{
    private static readonly string[] Watched = [.. Enumerable.Range(0, 26).Select(i => $"VB{i * 10}")];

    [Fact]
    public async Task Refresh_IdleStationWithTwoLists_OneReadChangesOfListsAndItsReplyOf22Characters()
    {
        var plc = SerialLineRig.Plc(2);
        await using var rig = await StartIdentifiedAsync(plc);
        var (received, sent) = (rig.Tap.Received.Length, rig.Tap.Sent.Length);

        var idle = await rig.RefreshAsync();

        idle.FramesFailed.Should().Be(0);
        Frames(rig.Tap.Received[received..]).Should().ContainSingle()
            .Which.Should().MatchRegex("^<02[0-9A-F]{2}0903[`a-o]{4}>$", "one 09 with MASK 03, 14 characters");
        Frames(rig.Tap.Sent[sent..]).Should().ContainSingle()
            .Which.Should().MatchRegex("^<02[0-9A-F]{2}8900[0-9A-F]{4}0000[`a-o]{4}>$", "K = 0 for list 1 and list 2, 22 characters");
    }

    [Fact]
    public async Task Refresh_ValueChangedInEachList_ArrivesThroughTheReadChangesOfListsPairs()
    {
        var plc = SerialLineRig.Plc(2);
        await using var rig = await StartIdentifiedAsync(plc);
        var first = rig.Bus.Plan.Frames.Single(f => f.List == 1);
        var second = rig.Bus.Plan.Frames.Single(f => f.List == 2);
        plc.Memory.V[first.Items[0].Offset] = 0x11;
        plc.Memory.V[second.Items[^1].Offset] = 0x5A;
        var (received, sent) = (rig.Tap.Received.Length, rig.Tap.Sent.Length);

        var result = await rig.RefreshAsync();

        result.FramesFailed.Should().Be(0);
        Frames(rig.Tap.Received[received..]).Should().ContainSingle().Which.Should().Contain("0903");
        var reply = Frames(rig.Tap.Sent[sent..]).Should().ContainSingle().Subject;
        var lastIndex = (second.DataBytes - 1).ToString("X2", CultureInfo.InvariantCulture);
        Payload(reply).Should().Be($"01001101{lastIndex}5A", "list 1: INDEX 0 = 11; list 2: its last byte = 5A");
        rig.Value(plc, $"VB{first.Items[0].Offset}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x11);
        rig.Value(plc, $"VB{second.Items[^1].Offset}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x5A);
        rig.Value(plc, $"VB{second.Items[0].Offset}").Quality.Should().Be(ValueQuality.Good, "an unchanged value stays Good");
    }

    /// <summary>The rig, the station identified (so the engine knows FEATURES bit 2), its lists defined and read FULL once.</summary>
    private static async Task<SerialLineRig> StartIdentifiedAsync(Simulator.Reference.ReferencePlc plc)
    {
        var rig = await SerialLineRig.StartAsync([plc], Watched);
        try
        {
            rig.Bus.Plan.ListCount.Should().Be(2);
            // The bus hears its own IDENTIFY: FEATURES bit 2 chooses the 09 reader for the station.
            var reply = await rig.Bus.IdentifyAsync(plc.Config.Station, CancellationToken.None).WaitAsync(SerialLineRig.Limit);
            var identity = reply.Response.Should().BeOfType<IdentifyResponse>().Subject;
            identity.HasChangesOfLists.Should().BeTrue("the reference model answers 09");
            await rig.RefreshUntilAsync(r => r.FramesFailed == 0);
            return rig;
        }
        catch
        {
            await rig.DisposeAsync();
            throw;
        }
    }

    /// <summary>A reply's payload: the hex after '&lt;' STATION SEQ CMD STATUS REQCHECK, before the 4 check characters and '&gt;'.</summary>
    private static string Payload(string reply) => reply[13..^5];

    private static List<string> Frames(string characters) => [.. Frame().Matches(characters).Select(m => m.Value)];

    [GeneratedRegex("<[^<>]*>")]
    private static partial Regex Frame();
}
