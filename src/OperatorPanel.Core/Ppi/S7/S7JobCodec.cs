using System.Buffers.Binary;
using System.Text;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// Job PDUs as the master writes them (<see cref="Read"/>, <see cref="Write"/> ...; the CPU side reads them with
/// <see cref="S7JobDecoder"/>). Layouts in docs/ppi.md section 5, from libnodave (davePrepareReadRequest,
/// daveAddToReadRequest, daveAddToWriteRequest, _daveNegPDUlengthRequest, paMakeStop/paMakeRun) and the captures there.
/// </summary>
public static class S7JobCodec
{
    /// <summary>"P_PROGRAM": the program the PI services STOP and RUN act on.</summary>
    internal static readonly byte[] ProgramName = Encoding.ASCII.GetBytes("P_PROGRAM");

    /// <summary>Job header and the two parameter bytes (function, item count) before the items.</summary>
    public const int ItemJobOverhead = S7Header.JobLength + 2;

    public static byte[] Read(ushort reference, IReadOnlyList<S7Item> items)
    {
        ArgumentNullException.ThrowIfNull(items);
        ArgumentOutOfRangeException.ThrowIfZero(items.Count, nameof(items));
        var parameters = Parameters(S7Function.ReadVariable, items.Select(i => i).ToList());
        return Pdu(reference, parameters, []);
    }

    public static byte[] Write(ushort reference, IReadOnlyList<S7WriteItem> items)
    {
        ArgumentNullException.ThrowIfNull(items);
        ArgumentOutOfRangeException.ThrowIfZero(items.Count, nameof(items));
        var parameters = Parameters(S7Function.WriteVariable, items.Select(i => i.Item).ToList());
        var data = new List<byte>();
        for (var i = 0; i < items.Count; i++)
        {
            var item = items[i];
            var length = item.DataSize == S7DataSize.Bit ? item.Data.Length : item.Data.Length * 8;
            data.AddRange([0x00, (byte)item.DataSize, (byte)(length >> 8), (byte)length]);
            data.AddRange(item.Data);
            if (item.Data.Length % 2 == 1 && i < items.Count - 1)
            {
                data.Add(0x00);
            }
        }

        return Pdu(reference, parameters, [.. data]);
    }

    /// <summary>Offers <paramref name="pduSize"/> bytes, one job at a time each way (libnodave: F0 00 00 01 00 01 PDU).</summary>
    public static byte[] SetupCommunication(ushort reference, int pduSize) =>
        Pdu(reference, [(byte)S7Function.SetupCommunication, 0x00, 0x00, 0x01, 0x00, 0x01, (byte)(pduSize >> 8), (byte)pduSize], []);

    /// <summary>STOP: 29 00 00 00 00 00 09 "P_PROGRAM" (libnodave paMakeStop).</summary>
    public static byte[] Stop(ushort reference) =>
        Pdu(reference, [(byte)S7Function.PlcStop, 0, 0, 0, 0, 0, (byte)ProgramName.Length, .. ProgramName], []);

    /// <summary>RUN: 28 00 00 00 00 00 00 FD 00 00 09 "P_PROGRAM" (libnodave paMakeRun).</summary>
    public static byte[] Run(ushort reference) =>
        Pdu(reference, [(byte)S7Function.PlcControl, 0, 0, 0, 0, 0, 0, 0xFD, 0, 0, (byte)ProgramName.Length, .. ProgramName], []);

    private static byte[] Parameters(S7Function function, List<S7Item> items)
    {
        var parameters = new byte[2 + (items.Count * S7Item.EncodedLength)];
        (parameters[0], parameters[1]) = ((byte)function, (byte)items.Count);
        for (var i = 0; i < items.Count; i++)
        {
            var item = items[i];
            var at = parameters.AsSpan(2 + (i * S7Item.EncodedLength), S7Item.EncodedLength);
            (at[0], at[1], at[2], at[3]) = (0x12, 0x0A, 0x10, (byte)item.Size);
            BinaryPrimitives.WriteUInt16BigEndian(at[4..], (ushort)item.Count);
            BinaryPrimitives.WriteUInt16BigEndian(at[6..], (ushort)item.DataBlock);
            (at[8], at[9], at[10], at[11]) = ((byte)item.Area, (byte)(item.Address >> 16), (byte)(item.Address >> 8), (byte)item.Address);
        }

        return parameters;
    }

    private static byte[] Pdu(ushort reference, byte[] parameters, byte[] data) => S7Header.Pdu(S7MessageType.Job, reference, parameters, data);
}
