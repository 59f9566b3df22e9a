using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Reference.V3;
using OperatorPanel.TestKit.ProtocolDoc;

namespace OperatorPanel.Simulator.Tests.Reference.V3;

/// <summary>
/// docs/protocol.md section 5 replayed against the reference model with the section's own setup: every reply the text
/// shows is what the model answers, byte for byte, in the text's order with the memory the text sets on the way.
/// </summary>
public sealed class ReferenceHandlerSection5Tests
{
    /// <summary>The section's first paragraph: the setup its frames were produced with.</summary>
    public const string Setup = "CPU 224\nCurrent, station 2, port 0, full handler with STOP, END_TIMEOUT_MS 4, V_FIRST 7586; scans of 12, 9, 15 and 11 ms\n"
        + "recorded; VB100-VB103 = 12 34 56 78, MB0 = 05, QB0 = 01, IB0 = 81.";

    [Fact]
    public void Section5_EveryReplyInTheText_IsTheReferenceModelsAnswer()
    {
        ProtocolSection5.Text().Should().Contain(Setup, "the setup below is the section's");
        var model = new ReferenceHandler(new HandlerSetup(new Station(2), CpuProfiles.For(CpuModel.Cpu224), HandlerShape.Full, 0, HandlerSetup.DefaultWriteMask, 4, allowStop: true));
        model.Setup.VFirst.Should().Be(7586);
        byte[] vb100 = [0x12, 0x34, 0x56, 0x78];
        vb100.CopyTo(model.Memory.V, 100);
        (model.Memory.M[0], model.Memory.Q[0], model.Memory.I[0]) = (0x05, 0x01, 0x81);
        ushort[] scans = [12, 9, 15, 11];
        for (var i = 0; i < scans.Length; i++)
        {
            model.CompleteScan(scans[i], first: i == 0);
        }

        var replayed = 0;
        foreach (var step in ProtocolSection5.Steps())
        {
            foreach (var (area, offset, value) in step.Pokes)
            {
                model.Memory.Area(area)[offset] = value;
            }

            if (step.Request is null || step.OtherHandler)
            {
                continue;
            }

            var answer = model.HandleMessage(step.Request);
            Convert.ToHexString(answer ?? []).Should().Be(Convert.ToHexString(step.Reply ?? []), step.Line);
            replayed++;
        }

        replayed.Should().BeGreaterThan(20, "section 5 has IDENTIFY, READ, WRITE, WRITE BITS, the list, the refusals, silence and STOP");
        model.Mode.Should().Be(Simulator.Reference.OperatingMode.Stop, "the section ends with STOP");
    }

    [Fact]
    public void Section5_TheCompactHandlersFrames_AreTheCompactReferenceModelsAnswers()
    {
        // "A compact handler (CPU 221, station 1, defaults)": END_TIMEOUT_MS 4, the default at 9600 8N1 (V3LinkOptions).
        var model = new ReferenceHandler(new HandlerSetup(new Station(1), CpuProfiles.For(CpuModel.Cpu221), HandlerShape.Compact, 0, HandlerSetup.DefaultWriteMask, 4));
        var compact = ProtocolSection5.Steps().Where(s => s.OtherHandler).ToList();

        compact.Should().HaveCount(2, "IDENTIFY in 5.1 and READ LIST in 5.6");
        foreach (var step in compact)
        {
            Convert.ToHexString(model.HandleMessage(step.Request!) ?? []).Should().Be(Convert.ToHexString(step.Reply ?? []), step.Line);
        }
    }
}
