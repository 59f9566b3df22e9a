using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Simulator.Stl.Ppi;

/// <summary>Does one job on the CPU's memory and writes its answer PDU (docs/ppi.md sections 5-7).</summary>
internal static class PpiJobRunner
{
    public static byte[] Run(S7Job job, IPpiMemory memory, int pduSize) => job switch
    {
        S7Job.Read read => Read(read, memory, pduSize),
        S7Job.Write write => S7AnswerCodec.Write(write.Reference, [.. write.Items.Select((item, i) =>
            write.Problems[i] == S7ReturnCode.Success ? memory.Write(item) : write.Problems[i])]),
        S7Job.SetupCommunication setup => S7AnswerCodec.SetupCommunication(setup.Reference, Math.Min(setup.PduSize, pduSize)),
        S7Job.Control control => memory.Control(control.Function)
            ? S7AnswerCodec.Control(control.Reference, control.Function)
            : S7AnswerCodec.Refusal(control.Reference, 0x80, 0x01),
        _ => S7AnswerCodec.Refusal(job.Reference, 0x81, 0x04),
    };

    /// <summary>An answer that would not fit the PDU is refused whole (16#8500, unconfirmed for the S7-200).</summary>
    private static byte[] Read(S7Job.Read read, IPpiMemory memory, int pduSize)
    {
        if (S7AnswerCodec.ReadAnswerLength(read.Items) > pduSize)
        {
            return S7AnswerCodec.Refusal(read.Reference, 0x85, 0x00);
        }

        return S7AnswerCodec.Read(read.Reference, [.. read.Items.Select(memory.Read)]);
    }
}
