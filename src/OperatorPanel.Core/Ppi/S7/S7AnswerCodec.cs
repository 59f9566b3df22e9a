namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// Answer PDUs as the CPU side writes them (docs/ppi.md section 5; the masters read them with <see cref="S7AnswerDecoder"/>):
/// an AckData header with error class and code 0, the job's function and item count as parameters, then per item a
/// return code, a size byte, a length and the bytes, an odd length padded with one byte unless the item is the last
/// (captured answers in docs/ppi.md; libnodave _daveDumpPDU "the PLC places extra bytes at the end of all but last result").
/// </summary>
public static class S7AnswerCodec
{
    /// <summary>Answer header, parameters and the first item's 4-byte header: a 240-byte PDU reads 222 data bytes (libnodave doc/FAQ.html).</summary>
    public const int ReadAnswerOverhead = S7Header.AnswerLength + 2 + 4;

    public static byte[] Read(ushort reference, IReadOnlyList<S7ItemResult> results)
    {
        ArgumentNullException.ThrowIfNull(results);
        var data = new List<byte>();
        for (var i = 0; i < results.Count; i++)
        {
            var result = results[i];
            if (!result.Succeeded)
            {
                data.AddRange([(byte)result.Code, 0x00, 0x00, 0x00]);
                continue;
            }

            var length = result.DataSize == S7DataSize.Bits ? result.Data.Length * 8 : result.Data.Length;
            data.AddRange([(byte)S7ReturnCode.Success, (byte)result.DataSize, (byte)(length >> 8), (byte)length]);
            data.AddRange(result.Data);
            if (result.Data.Length % 2 == 1 && i < results.Count - 1)
            {
                data.Add(0x00);
            }
        }

        return Answer(reference, [(byte)S7Function.ReadVariable, (byte)results.Count], [.. data]);
    }

    public static byte[] Write(ushort reference, IReadOnlyList<S7ReturnCode> codes)
    {
        ArgumentNullException.ThrowIfNull(codes);
        return Answer(reference, [(byte)S7Function.WriteVariable, (byte)codes.Count], [.. codes.Select(c => (byte)c)]);
    }

    public static byte[] SetupCommunication(ushort reference, int pduSize) =>
        Answer(reference, [(byte)S7Function.SetupCommunication, 0x00, 0x00, 0x01, 0x00, 0x01, (byte)(pduSize >> 8), (byte)pduSize], []);

    /// <summary>STOP or RUN done: the function byte alone as parameters (iottree PPIMsgReqRunStop capture).</summary>
    public static byte[] Control(ushort reference, S7Function function) => Answer(reference, [(byte)function], []);

    /// <summary>The whole job refused: an Ack header carrying error class and code, nothing else (e.g. 16#8500 "incorrect PDU size").</summary>
    public static byte[] Refusal(ushort reference, byte errorClass, byte errorCode)
    {
        var pdu = new byte[S7Header.AnswerLength];
        new S7Header(S7MessageType.Ack, reference, 0, 0, errorClass, errorCode).WriteTo(pdu);
        return pdu;
    }

    /// <summary>Bytes an answer to a read of <paramref name="items"/> takes, padding included: what must fit the PDU size.</summary>
    public static int ReadAnswerLength(IReadOnlyList<S7Item> items)
    {
        ArgumentNullException.ThrowIfNull(items);
        var length = S7Header.AnswerLength + 2;
        for (var i = 0; i < items.Count; i++)
        {
            var data = items[i].DataLength;
            length += 4 + data + (data % 2 == 1 && i < items.Count - 1 ? 1 : 0);
        }

        return length;
    }

    private static byte[] Answer(ushort reference, byte[] parameters, byte[] data) => S7Header.Pdu(S7MessageType.AckData, reference, parameters, data);
}
