using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The generated v3 handler, executed in the STL interpreter, against the reference model byte for byte: each command,
/// its refusals in docs/protocol.md section 4's order, and silence for frames it must not answer.
/// </summary>
public sealed class V3DifferentialTests
{
    private static V3Station Full(CpuModel cpu = CpuModel.Cpu224, bool stop = true, int seed = 3) =>
        new(new HandlerOptions { Cpu = CpuProfiles.For(cpu), Station = 2, AllowStop = stop }, new Random(seed));

    private static V3Station Compact(CpuModel cpu = CpuModel.Cpu221) =>
        new(new HandlerOptions { Cpu = CpuProfiles.For(cpu), Station = 5, Compact = true }, new Random(4));

    private static string Same(V3Station station, byte[] message)
    {
        var (stl, reference) = station.Exchange(message);
        Convert.ToHexString(stl).Should().Be(Convert.ToHexString(reference), $"the handler answers {Convert.ToHexString(message)} like the reference model");
        return Convert.ToHexString(stl);
    }

    private static string Same(V3Station station, Request request) => Same(station, Codec.Encode(request));

    [Theory]
    [InlineData(CpuModel.Cpu221)]
    [InlineData(CpuModel.Cpu222)]
    [InlineData(CpuModel.Cpu224)]
    [InlineData(CpuModel.Cpu224XP)]
    [InlineData(CpuModel.Cpu226)]
    public void Identify_EveryCpu_AnswersTheReferencesPayload(CpuModel cpu)
    {
        var station = Full(cpu);

        var reply = Same(station, Request.Identify(station.Station, 1));

        reply.Should().StartWith("3C2180", "LEN 33 (5 head bytes, 24 payload bytes, 4 check bytes), STATUS 80");
    }

    [Theory]
    [InlineData(ProtocolArea.V, 0, 1)]
    [InlineData(ProtocolArea.V, 100, 37)]
    [InlineData(ProtocolArea.M, 28, 4)]
    [InlineData(ProtocolArea.I, 0, 16)]
    [InlineData(ProtocolArea.Q, 15, 1)]
    [InlineData(ProtocolArea.SM, 30, 20)]
    [InlineData(ProtocolArea.V, 8191, 1)]
    [InlineData(ProtocolArea.V, 8000, 128)]
    [InlineData(ProtocolArea.V, 8191, 2)]
    [InlineData(ProtocolArea.M, 32, 1)]
    [InlineData((ProtocolArea)0, 0, 1)]
    [InlineData((ProtocolArea)6, 0, 1)]
    [InlineData(ProtocolArea.V, 0, 0)]
    [InlineData(ProtocolArea.V, 0x2800, 1)]
    [InlineData(ProtocolArea.V, 0xFFFF, 1)]
    public void Read_ItemsAndRefusals_AnswerLikeTheReference(ProtocolArea area, int offset, int length)
    {
        var station = Full();

        Same(station, Request.Read(station.Station, 2, new ReadItem(area, offset, length)));
    }

    [Theory]
    [InlineData(ProtocolArea.V, 200, "11223344")]
    [InlineData(ProtocolArea.M, 31, "7F")]
    [InlineData(ProtocolArea.Q, 0, "0102")]
    [InlineData(ProtocolArea.I, 0, "01")]
    [InlineData(ProtocolArea.SM, 40, "01")]
    [InlineData(ProtocolArea.V, 7000, "01")]
    [InlineData(ProtocolArea.V, 8191, "0102")]
    public void Write_DataAndRefusals_AnswerLikeTheReference(ProtocolArea area, int offset, string data)
    {
        var station = Full();

        Same(station, Request.Write(station.Station, 3, area, offset, Convert.FromHexString(data)));
        Same(station, Request.Read(station.Station, 4, new ReadItem(ProtocolArea.V, 200, 4)));
    }

    [Fact]
    public void Write_TheHandlersOwnBytes_IsRefused()
    {
        var station = Full();
        var first = station.Generated.Stats!.FirstVByte;

        Same(station, Request.Write(station.Station, 3, ProtocolArea.V, first - 1, [1, 2])).Substring(4, 2).Should().Be("83");
        Same(station, Request.Write(station.Station, 4, ProtocolArea.V, first - 2, [1, 2])).Substring(4, 2).Should().Be("80");
    }

    [Theory]
    [InlineData(ProtocolArea.Q, 1, 0x08, 0xFF)]
    [InlineData(ProtocolArea.M, 31, 0x80, 0x00)]
    [InlineData(ProtocolArea.V, 10, 0x0F, 0x5A)]
    [InlineData(ProtocolArea.V, 11, 0x00, 0xFF)]
    [InlineData(ProtocolArea.M, 0, 0xFF, 0x3C)]
    [InlineData(ProtocolArea.I, 0, 0x01, 0x01)]
    [InlineData(ProtocolArea.SM, 0, 0x01, 0x01)]
    [InlineData(ProtocolArea.Q, 16, 0x01, 0x01)]
    public void WriteBits_MaskAndValueAndRefusals_AnswerLikeTheReference(ProtocolArea area, int offset, int mask, int value)
    {
        var station = Full();

        Same(station, Request.WriteBits(station.Station, 5, area, offset, (byte)mask, (byte)value));
    }

    [Theory]
    [InlineData("01", "")]
    [InlineData("02", "040000")]
    [InlineData("03", "04000001")]
    [InlineData("04", "040000010203")]
    [InlineData("0F", "")]
    [InlineData("0E", "")]
    [InlineData("0B", "")]
    [InlineData("06", "00")]
    [InlineData("00", "")]
    [InlineData("09", "01")]
    [InlineData("08", "53544F51")]
    [InlineData("08", "535441")]
    public void OddPayloads_AnswerTheFirstFailingCheckLikeTheReference(string command, string payload)
    {
        var station = Full();
        var request = new Request(station.Station, 7, (Command)Convert.ToByte(command, 16), [.. Convert.FromHexString(payload)]);

        Same(station, request);
    }

    [Fact]
    public void Silence_BadCheckOtherStationOrWrongLength_NoReplyFromEither()
    {
        var station = Full();
        var good = Codec.Encode(Request.Identify(station.Station, 1));
        var badCheck = (byte[])good.Clone();
        badCheck[^1] ^= 0x10;
        var other = Codec.Encode(Request.Identify(new Core.Addressing.Station(3), 1));
        var longer = (byte[])good.Clone();
        longer[1]++;

        Same(station, badCheck).Should().BeEmpty();
        Same(station, other).Should().BeEmpty();
        Same(station, longer).Should().BeEmpty();
        Same(station, good).Should().NotBeEmpty("the station answers again at once");
    }

    [Fact]
    public void Compact_ListCommandsAndStop_AreUnknown()
    {
        var station = Compact();

        Same(station, Request.Identify(station.Station, 1));
        Same(station, Request.ReadList(station.Station, 2)).Substring(4, 2).Should().Be("85");
        Same(station, Request.Stop(station.Station, 3)).Substring(4, 2).Should().Be("85");
        Same(station, Request.Read(station.Station, 4, new ReadItem(ProtocolArea.V, 1000, 48)));
        Same(station, Request.Write(station.Station, 5, ProtocolArea.M, 0, [1, 2, 3, 4]));
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void WriteBits_StoresTheTargetByteOnce(bool compact)
    {
        // An AND then an OR into the target stored it twice: a bit written 1 over a 1 was 0 between the two stores for
        // an interrupt routine of the user's program. Every other instruction of the network only reads the target.
        var awl = HandlerGenerator.Generate(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 5, Compact = compact }).AwlText;
        var network = awl[awl.IndexOf("// WRITE BITS: one store", StringComparison.Ordinal)..];
        network = network[..network.IndexOf("Network", StringComparison.Ordinal)];
        var lines = network.Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0 && !l.StartsWith("//", StringComparison.Ordinal)).ToList();

        var stores = lines.Where(l => System.Text.RegularExpressions.Regex.IsMatch(l, @"^(MOVB|ANDB|ORB|XORB|INVB)\s.*\*VD\d+$")).ToList();

        stores.Should().ContainSingle().Which.Should().StartWith("XORB   AC0, *VD");
    }

    [Fact]
    public void Compact_StopAllowed_RefusedAsImpossibleInsteadOfLeftOutSilently()
    {
        var result = HandlerGenerator.Generate(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu222), Station = 5, Compact = true, AllowStop = true });

        result.Ok.Should().BeFalse("a compact handler has no STOP: generating it would drop the STOP that was allowed");
        result.Diagnostics.Select(d => d.Id).Should().Equal(StlDiagnostics.CompactHandlerHasNoStop);
    }

    [Fact]
    public void Compact_Stop_IsUnknownAndLeavesNoStopCode()
    {
        var station = new V3Station(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu222), Station = 5, Compact = true }, new Random(6));

        Same(station, Request.Stop(station.Station, 1)).Substring(4, 2).Should().Be("85", "the compact handler has no 08 STOP");
        station.Plc.Mode.Should().Be(Simulator.Reference.OperatingMode.Run);
        station.Generated.AwlText.Should().NotMatchRegex(@"(?m)^STOP\b", "no STOP instruction in a compact handler");
        station.Generated.Stats!.StopEnabled.Should().BeFalse();
    }

    [Fact]
    public void Stop_AnswersThenStops()
    {
        var station = Full();

        Same(station, Request.Stop(station.Station, 1)).Substring(4, 2).Should().Be("80");
        station.Plc.Mode.Should().Be(Simulator.Reference.OperatingMode.Stop);
    }
}
