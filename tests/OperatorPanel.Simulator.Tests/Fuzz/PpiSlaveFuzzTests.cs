using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Simulator.Stl.Ppi;
using OperatorPanel.Simulator.Tests.Stl;
using OperatorPanel.TestKit;

namespace OperatorPanel.Simulator.Tests.Fuzz;

/// <summary>A stranger's master sends anything: the CPU's PPI side answers or stays silent, and never throws.</summary>
public sealed class PpiSlaveFuzzTests
{
    [Fact]
    public void ReceiveAndServe_MutatedCapturedJobs_NeverThrowAndEveryAnswerIsAnS7Answer()
    {
        var plc = StlTestPrograms.Plc("NOP 0");
        var memory = new StlPpiMemory(plc);
        var slave = new PpiSlave(new PpiSettings());
        var random = new Random(22);
        string[] jobs = [PpiCaptures.ReadSevenItemsRequest, PpiCaptures.WriteVd300Request, PpiCaptures.ReadTimersRequest, PpiCaptures.ReadVb300Request];
        foreach (var job in jobs)
        {
            var pdu = PpiCaptures.Pdu(job);
            for (var round = 0; round < 500; round++)
            {
                var mutated = (byte[])pdu.Clone();
                for (var changes = random.Next(1, 4); changes > 0; changes--)
                {
                    mutated[random.Next(mutated.Length)] = (byte)random.Next(256);
                }

                slave.Receive(PpiFrame.Variable(2, 0, PpiFunctionCode.FirstRequest, mutated)).Should().Be(PpiFrame.ShortAcknowledge);
                slave.Serve(memory);
                var answer = slave.Receive(PpiFrame.Fixed(2, 0, PpiFunctionCode.Poll(round % 2 == 0)));

                answer!.Kind.Should().Be(PpiFrameKind.Variable);
                S7Header.TryRead(answer.Data.AsSpan(), out var header, out var error).Should().BeTrue(error.ToString());
                header.Type.Should().BeOneOf(S7MessageType.Ack, S7MessageType.AckData);
            }
        }
    }
}
