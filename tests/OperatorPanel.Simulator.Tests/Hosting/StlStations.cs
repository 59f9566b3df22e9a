using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Tests.Hosting;

/// <summary>STL stations loaded from the embedded generated handlers (Handler224Station2.awl, ...Station3.awl).</summary>
internal static class StlStations
{
    public static readonly CpuProfile Cpu224 = CpuProfiles.For(CpuModel.Cpu224);

    public static StlStation Load(int station)
    {
        using var stream = typeof(StlStations).Assembly.GetManifestResourceStream($"Handler224Station{station}.awl")!;
        using var reader = new StreamReader(stream);
        StlStation.TryCreate(reader.ReadToEnd(), Cpu224, 0, LineSettings.Default, out var loaded, out var error).Should().BeTrue(error);
        return loaded!;
    }

    public static StlLine Line(bool runProcess, params int[] stations)
    {
        var line = new StlLine(LineSettings.Default);
        foreach (var station in stations)
        {
            line.Attach(Load(station), runProcess);
        }

        // The first scans set the port to Freeport and start the receive.
        line.RunUntil(TimeSpan.FromMilliseconds(50));
        return line;
    }

    public static byte[] Identify(int station, byte sequence = 1) => RequestCodec.Encode(new IdentifyRequest(new Station(station), sequence));

    public static byte[] Read(int station, ProtocolArea area, int offset, int length, byte sequence = 1) =>
        RequestCodec.Encode(new ReadRequest(new Station(station), sequence, [new ReadItem(area, offset, length)]));

    public static byte[] Write(int station, ProtocolArea area, int offset, ImmutableArray<byte> data, byte sequence = 1) =>
        RequestCodec.Encode(new WriteBlockRequest(new Station(station), sequence, area, offset, data));

    /// <summary>Delivers <paramref name="request"/> now and runs the line <paramref name="for"/> further; what came back.</summary>
    public static IReadOnlyList<WireCharacter> Exchange(StlLine line, byte[] request, TimeSpan @for)
    {
        line.Deliver(request);
        line.RunUntil(line.Now + @for);
        return line.TakeCharacters();
    }

    /// <summary>The data of a good reply: its payload after STATUS 00 and REQCHECK.</summary>
    public static byte[] Data(IEnumerable<WireCharacter> characters)
    {
        var payload = Decode(characters).Payload;
        payload[0].Should().Be(0x00, "STATUS 00");
        return [.. payload.Skip(ProtocolLimits.ReplyHeaderBytes - FreeportFrame.OverheadBytes)];
    }

    public static FreeportFrame Decode(IEnumerable<WireCharacter> characters)
    {
        FrameCodec.TryDecode([.. characters.Select(c => c.Value)], out var frame, out var error).Should().BeTrue($"the reply must be one valid frame ({error})");
        return frame;
    }
}
