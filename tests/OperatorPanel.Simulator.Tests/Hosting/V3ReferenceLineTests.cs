using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference.V3;

namespace OperatorPanel.Simulator.Tests.Hosting;

/// <summary>The reference stations' line: deaf while a reply goes out, as docs/protocol.md section 4 and the generated handler are.</summary>
public sealed class V3ReferenceLineTests
{
    private static readonly Station Two = new(2);
    private static readonly TimeSpan Character = TimeSpan.FromMilliseconds(10.0 / 9.6);

    [Fact]
    public void Deliver_RequestWhileTheReplyGoesOut_IsLostThenTheSameRequestAfterItIsAnswered()
    {
        var line = new V3ReferenceLine([new ReferenceHandler(new HandlerSetup(Two, CpuProfiles.For(CpuModel.Cpu224)))]) { CharacterTime = Character };
        var read = Codec.Encode(Request.Read(Two, 1, new ReadItem(ProtocolArea.M, 0, 1)));

        line.Deliver(Codec.Encode(Request.Identify(Two, 0)));
        line.RunUntil(TimeSpan.FromMilliseconds(20)); // 8 characters (8.3 ms) + END_TIMEOUT_MS 4: the 33-byte reply leaves from 12.3 ms to 46.7 ms
        line.Deliver(read);
        line.RunUntil(TimeSpan.FromMilliseconds(100));

        line.Replies.Should().Be(1, "the READ arrived while the IDENTIFY's reply was still going out");
        line.Deliver(read);
        line.RunUntil(TimeSpan.FromMilliseconds(200));
        line.Replies.Should().Be(2);
        line.TakeTransmitted().Should().HaveCount(33 + 10);
    }
}
