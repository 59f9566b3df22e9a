using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;
using OperatorPanel.TestKit.ProtocolDoc;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// docs/protocol.md section 5 replayed against the generated handler in the STL interpreter, with the section's setup
/// (CPU 224, station 2, full handler with STOP, END_TIMEOUT_MS 4; every other byte of I, Q, M and V zero): every reply
/// the text shows is what the handler sends, byte for byte, except IDENTIFY's scan times (the interpreter's own) and
/// so its check.
/// </summary>
public sealed class V3Section5Tests
{
    [Fact]
    public void Section5_EveryReplyInTheText_IsWhatTheGeneratedHandlerSends()
    {
        var station = new V3Station(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2, AllowStop = true, CharTimeoutMs = 4 }, new ZeroRandom());
        station.Generated.Stats!.FirstVByte.Should().Be(7586, "section 5's V_FIRST");
        station.Poke(Core.Protocol.ProtocolArea.V, 100, 0x12, 0x34, 0x56, 0x78);
        station.Poke(Core.Protocol.ProtocolArea.M, 0, 0x05);
        station.Poke(Core.Protocol.ProtocolArea.Q, 0, 0x01);
        station.Poke(Core.Protocol.ProtocolArea.I, 0, 0x81);
        var replayed = 0;
        foreach (var step in ProtocolSection5.Steps())
        {
            foreach (var (area, offset, value) in step.Pokes)
            {
                station.Poke(area, offset, value);
            }

            if (step.Request is null || step.OtherHandler)
            {
                continue;
            }

            var (stl, _) = station.Exchange(step.Request);
            Convert.ToHexString(stl).Should().Be(Convert.ToHexString(V3Station.Masked(step.Reply ?? [], step.Request)), step.Line);
            replayed++;
        }

        replayed.Should().BeGreaterThan(20);
        station.Plc.Mode.Should().Be(Simulator.Reference.OperatingMode.Stop, "the section ends with STOP");
    }

    [Fact]
    public void Section5_TheCompactHandlersFrames_AreWhatTheGeneratedCompactHandlerSends()
    {
        var station = new V3Station(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu221), Station = 1, Compact = true }, new ZeroRandom());
        var compact = ProtocolSection5.Steps().Where(s => s.OtherHandler).ToList();

        compact.Should().HaveCount(2, "IDENTIFY in 5.1 and READ LIST in 5.6");
        foreach (var step in compact)
        {
            var (stl, _) = station.Exchange(step.Request!);
            Convert.ToHexString(stl).Should().Be(Convert.ToHexString(V3Station.Masked(step.Reply ?? [], step.Request!)), step.Line);
        }
    }

    /// <summary>Memory of zeros, as the section assumes beside the bytes it names.</summary>
    private sealed class ZeroRandom : Random
    {
        public override void NextBytes(byte[] buffer) => Array.Clear(buffer);

        public override void NextBytes(Span<byte> buffer) => buffer.Clear();
    }
}
