using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The compact handler (IDENTIFY, READ, WRITE, WRITE BITS) executed in the STL interpreter against the reference model
/// byte for byte, one station serving a whole sequence of requests: every command, the ends of every area, every
/// refusal, and silence. Its replies leave whole, in one XMT once their check is in place (no pause between characters).
/// </summary>
public sealed class V3CompactTests
{
    public static TheoryData<CpuModel, int> Stations => new()
    {
        { CpuModel.Cpu221, 0 },
        { CpuModel.Cpu222, 0 },
        { CpuModel.Cpu224XP, 1 },
    };

    /// <summary>The next SEQ (4 bits: 1-15, 0, 1, ...), as the panel takes it for a new request.</summary>
    private static byte Next(ref byte seq) => seq = (byte)((seq + 1) % Limits.SequenceCount);

    private static V3Station Compact(CpuModel cpu, int port, int seed) =>
        new(new HandlerOptions { Cpu = CpuProfiles.For(cpu), Station = 9, Port = port, Compact = true }, new Random(seed));

    /// <summary>The reply, checked against the reference, and (when there is one) sent without a pause.</summary>
    private static string Same(V3Station station, Request request)
    {
        var (stl, reference) = station.Exchange(Codec.Encode(request));
        var hex = Convert.ToHexString(stl);
        hex.Should().Be(Convert.ToHexString(reference), $"the compact handler answers {request.Command} {Convert.ToHexString(request.Payload.ToArray())} like the reference model");
        if (stl.Length > 0)
        {
            station.LongestPause.Should().Be(TimeSpan.Zero, "a compact handler's reply leaves whole in one XMT");
        }

        return hex;
    }

    [Theory]
    [InlineData(72)]
    [InlineData(137)]
    public void LongerFrameOnTheBus_WhoseTailIsAFrameForThisStation_GetsNoReply(int length)
    {
        // Another station's DEFINE LIST or list reply may carry any bytes; a compact handler whose receive ended at 33
        // bytes restarted at once and answered such a tail as a request (two stations talking at once).
        var station = Compact(CpuModel.Cpu221, 0, 3);
        byte seq = 0;
        var own = Codec.Encode(Request.Identify(station.Station, Next(ref seq)));
        var frame = Enumerable.Repeat((byte)0x55, length).ToArray();
        (frame[0], frame[1], frame[2], frame[3]) = (Limits.Start, (byte)length, 17, 0x05);
        own.CopyTo(frame, length - own.Length);

        var (stl, reference) = station.Exchange(frame);

        stl.Should().BeEmpty("the frame is station 17's; its tail is only data");
        reference.Should().BeEmpty();
        Same(station, Request.Identify(station.Station, Next(ref seq))).Should().StartWith("3C2180", "the station still answers its own next request");
    }

    [Theory]
    [MemberData(nameof(Stations))]
    public void Reads_EveryAreaToItsEnd_AnswerLikeTheReference(CpuModel cpu, int port)
    {
        var station = Compact(cpu, port, 11);
        var v = CpuProfiles.For(cpu).TryGetArea(MemoryArea.V, out var area) ? area.ByteCount : 0;
        byte seq = 0;
        string Read(ProtocolArea a, int offset, int length) => Same(station, Request.Read(station.Station, Next(ref seq), new ReadItem(a, offset, length)));

        Same(station, Request.Identify(station.Station, Next(ref seq))).Should().StartWith("3C2180");
        Read(ProtocolArea.V, 0, 1).Substring(4, 2).Should().Be("80");
        Read(ProtocolArea.V, station.Generated.Stats!.FirstVByte - 16, 16).Substring(4, 2).Should().Be("80", "the 16 bytes before the handler's own (the reference model keeps those zero)");
        Read(ProtocolArea.V, v - 1, 1).Substring(4, 2).Should().Be("80", "the last byte of V");
        Read(ProtocolArea.V, v - 1, 2).Substring(4, 2).Should().Be("82", "one byte past V");
        Read(ProtocolArea.M, 28, 4).Substring(4, 2).Should().Be("80");
        Read(ProtocolArea.M, 32, 1).Substring(4, 2).Should().Be("82");
        Read(ProtocolArea.I, 0, 16).Substring(4, 2).Should().Be("80");
        Read(ProtocolArea.Q, 15, 1).Substring(4, 2).Should().Be("80");
        Read(ProtocolArea.SM, 30, 16).Substring(4, 2).Should().Be("82", "SM is not served: no &SMB pointer");
        Read(ProtocolArea.V, 0, 17).Substring(4, 2).Should().Be("84", "more than MAX_DATA");
        Read(ProtocolArea.V, 0, 0).Substring(4, 2).Should().Be("84");
        Read((ProtocolArea)0, 0, 1).Substring(4, 2).Should().Be("82");
        Read((ProtocolArea)6, 0, 1).Substring(4, 2).Should().Be("82");
        Read(ProtocolArea.V, 0x2800, 1).Substring(4, 2).Should().Be("82");
        Read(ProtocolArea.V, 0xFFFF, 1).Substring(4, 2).Should().Be("82");
    }

    [Theory]
    [MemberData(nameof(Stations))]
    public void Writes_DataBitsAndRefusals_AnswerLikeTheReferenceAndReadBack(CpuModel cpu, int port)
    {
        var station = Compact(cpu, port, 12);
        var first = station.Generated.Stats!.FirstVByte;
        byte seq = 0;
        string Write(ProtocolArea a, int offset, params byte[] data) => Same(station, Request.Write(station.Station, Next(ref seq), a, offset, data));
        string Bits(ProtocolArea a, int offset, byte mask, byte value) => Same(station, Request.WriteBits(station.Station, Next(ref seq), a, offset, mask, value));

        Write(ProtocolArea.V, 200, 0x11, 0x22, 0x33, 0x44).Substring(4).Should().StartWith("80").And.Subject.Substring(6, 8).Should().Be("11223344", "WRITE answers with the bytes read back");
        Write(ProtocolArea.M, 31, 0x7F).Substring(4, 2).Should().Be("80");
        Write(ProtocolArea.Q, 0, 1, 2).Substring(4, 2).Should().Be("80");
        Write(ProtocolArea.I, 0, 1).Substring(4, 2).Should().Be("83");
        Write(ProtocolArea.SM, 40, 1).Substring(4, 2).Should().Be("82", "SM is not served: the item check refuses it before the write checks");
        Write(ProtocolArea.V, first - 1, 1, 2).Substring(4, 2).Should().Be("83", "the handler's own first byte");
        Write(ProtocolArea.V, first - 2, 1, 2).Substring(4, 2).Should().Be("80", "the two bytes before it");
        Bits(ProtocolArea.V, 200, 0x0F, 0x05).Substring(4, 2).Should().Be("80");
        Same(station, Request.Read(station.Station, Next(ref seq), new ReadItem(ProtocolArea.V, 200, 1))).Substring(10, 2).Should().Be("15", "16#11 with its low nibble set to 5");
        Bits(ProtocolArea.M, 0, 0xFF, 0x3C).Substring(4, 2).Should().Be("80");
        Bits(ProtocolArea.I, 0, 0x01, 0x01).Substring(4, 2).Should().Be("83");
        Bits(ProtocolArea.Q, 16, 0x01, 0x01).Substring(4, 2).Should().Be("82");
    }

    [Theory]
    [MemberData(nameof(Stations))]
    public void OddFramesAndSilence_AnswerTheFirstFailingCheckOrNothing(CpuModel cpu, int port)
    {
        var station = Compact(cpu, port, 13);
        byte seq = 0;
        foreach (var (command, payload) in new (int, string)[] { (0x02, "040000"), (0x03, "04000001"), (0x04, "040000010203"), (0x05, ""), (0x06, ""), (0x0F, ""), (0x00, "") })
        {
            Same(station, new Request(station.Station, Next(ref seq), (Command)command, [.. Convert.FromHexString(payload)])).Substring(4, 2).Should().BeOneOf("84", "85");
        }

        var good = Codec.Encode(Request.Identify(station.Station, Next(ref seq)));
        var badCheck = (byte[])good.Clone();
        badCheck[^1] ^= 0x10;
        station.Exchange(badCheck).Stl.Should().BeEmpty("a frame whose check differs gets no reply");
        station.Exchange(Codec.Encode(Request.Identify(new Station(3), Next(ref seq)))).Stl.Should().BeEmpty("another station's request");
        Same(station, Request.Identify(station.Station, Next(ref seq))).Should().StartWith("3C2180", "the station answers again at once");
    }
}
