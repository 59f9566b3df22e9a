using System.Text.RegularExpressions;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>Stored lists end to end over a socat pty: commands counted from the characters the PLC end received.</summary>
public sealed partial class PollingEngineSerialListTests
{
    private static readonly string[] Watched = ["IB0", "MW10", "VD100", "VW2000", "V3000.5"];

    [Fact]
    public async Task Refresh_SteadyState_PollsWithReadChangesOnly()
    {
        var plc = SerialLineRig.Plc(2);
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 123_456);
        await using var rig = await SerialLineRig.StartAsync([plc], Watched);

        for (var i = 0; i < 4; i++)
        {
            await rig.RefreshUntilAsync(r => r.FramesFailed == 0);
        }

        var commands = Commands(rig.Tap.Received);
        commands.Count(c => c == CommandCode.DefineList).Should().Be(rig.Bus.Plan.FrameCount);
        commands.Skip(rig.Bus.Plan.FrameCount * 2).Should().NotBeEmpty().And.OnlyContain(c => c == CommandCode.ReadChanges);
        rig.Value(plc, "VD100").Raw.Should().Equal(0x00, 0x01, 0xE2, 0x40);
    }

    [Fact]
    public async Task Refresh_AfterALongWriteWipedTheLists_RedefinesAndReturnsCorrectValues()
    {
        var plc = SerialLineRig.Plc(2);
        await using var rig = await SerialLineRig.StartAsync([plc], Watched);
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);
        System.Collections.Immutable.ImmutableArray<byte> block = [.. Enumerable.Range(0, ProtocolLimits.MaxWriteData).Select(i => (byte)i)];

        // 18 + 2 x 118 = 254 characters: the request reaches every list in the tail. Typed writes are at most 4 bytes, so
        // the block goes over the same link (another client of the bus, e.g. a recipe download).
        var write = await rig.Bus.ExchangeAsync(new WriteBlockRequest(plc.Config.Station, 0x77, ProtocolArea.V, 4000, block), CancellationToken.None)
            .WaitAsync(SerialLineRig.Limit);
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 7_654_321);
        plc.Memory.WriteWord(ProtocolArea.V, 2000, 0x1234);
        var before = Commands(rig.Tap.Received).Count;
        var result = await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        write.Response.Should().BeOfType<WriteBlockResponse>();
        plc.Lists.Floor.Should().BeLessThan(256, "the lists were defined again");
        result.FramesFailed.Should().Be(0);
        Commands(rig.Tap.Received).Skip(before).Take(4).Should().Equal(
            [CommandCode.ReadChanges, CommandCode.DefineList, CommandCode.DefineList, CommandCode.ReadChanges], "07, the clearing DEFINE, the DEFINE, READ CHANGES FULL");
        rig.Value(plc, "VD100").Raw.Should().Equal(0x00, 0x74, 0xCB, 0xB1);
        rig.Value(plc, "VW2000").Raw.Should().Equal(0x12, 0x34);
    }

    [Fact]
    public async Task Refresh_ValuesChangedAfterTheFirstFull_ReadChangesWithoutFullBringsThemRight()
    {
        var plc = SerialLineRig.Plc(2);
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 1);
        await using var rig = await SerialLineRig.StartAsync([plc], Watched);
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 0x01020304);
        plc.Memory.WriteWord(ProtocolArea.M, 10, 0xBEEF);
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        ChangesFlags(rig.Tap.Received).Should().Contain("00", "steady READ CHANGES ask for the changed bytes only");
        rig.Value(plc, "VD100").Should().Match<Core.Polling.PolledValue>(v => v.Quality == Core.Polling.ValueQuality.Good);
        rig.Value(plc, "VD100").Raw.Should().Equal(0x01, 0x02, 0x03, 0x04);
        rig.Value(plc, "MW10").Raw.Should().Equal(0xBE, 0xEF);
        rig.Value(plc, "IB0").Quality.Should().Be(Core.Polling.ValueQuality.Good, "an unchanged value stays Good");
    }

    /// <summary>The FLAGS byte of every READ CHANGES the PLC end heard.</summary>
    private static List<string> ChangesFlags(string received) =>
        [.. ReadChanges().Matches(received).Select(m => m.Groups[1].Value)];

    [GeneratedRegex("<[0-9A-F]{4}08[0-9A-F]{2}([0-9A-F]{2})")]
    private static partial Regex ReadChanges();

    /// <summary>The commands the PLC end heard, one per request: a link retry resends the same SEQ and counts once.</summary>
    private static List<CommandCode> Commands(string received)
    {
        var commands = new List<CommandCode>();
        string? lastSequence = null;
        foreach (Match match in Request().Matches(received))
        {
            if (match.Groups[1].Value != lastSequence)
            {
                commands.Add((CommandCode)Convert.ToByte(match.Groups[2].Value, 16));
            }

            lastSequence = match.Groups[1].Value;
        }

        return commands;
    }

    /// <summary>'&lt;' STATION SEQ CMD of a request (CMD bit 7 clear): the PLC end hears requests only.</summary>
    [GeneratedRegex("<[0-9A-F]{2}([0-9A-F]{2})([0-7][0-9A-F])")]
    private static partial Regex Request();
}
