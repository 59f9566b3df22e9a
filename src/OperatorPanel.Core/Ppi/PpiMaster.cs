using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// A PPI master on an <see cref="ITransport"/>: the panel as the only master on the bus, reading and writing S7-200s
/// without any program in them (docs/ppi.md section 4). One exchange: the job goes out in an SD2 request (FC 16#6C),
/// the CPU acknowledges it with 16#E5, and the master polls with SD1 frames (FC 16#5C, 16#7C, alternating the frame
/// count bit) until the CPU, having handled the job in its scan's communication phase, answers with the data. Reads
/// repeat an unacknowledged job, writes send theirs once; both repeat a poll without a sound answer. The
/// master never passes a token: seeing another master's frames ends the exchange with
/// <see cref="PlcErrorKind.AnotherMaster"/>. Failures are <see cref="PlcCommunicationException"/>s. One exchange at
/// a time: the bus owner serialises calls.
/// </summary>
public sealed partial class PpiMaster
{
    private readonly ITransport _transport;
    private readonly TimeProvider _time;
    private readonly ILogger _log;
    private readonly PpiFrameReader _reader = new();
    private readonly byte[] _buffer = new byte[512];
    private ushort _reference;

    public PpiMaster(ITransport transport, PpiMasterOptions? options = null, TimeProvider? time = null, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(transport);
        _transport = transport;
        Options = options ?? new PpiMasterOptions();
        _time = time ?? TimeProvider.System;
        _log = (log ?? Serilog.Core.Logger.None).ForContext<PpiMaster>();
    }

    public PpiMasterOptions Options { get; }

    /// <summary>Jobs answered.</summary>
    public int Exchanges { get; private set; }

    /// <summary>Polls answered "no data yet" (16#E5): the CPU had not reached its communication phase.</summary>
    public int EmptyPolls { get; private set; }

    /// <summary>Requests and polls sent again after a missing or garbled answer.</summary>
    public int Repeats { get; private set; }

    public async Task<ImmutableArray<S7ItemResult>> ReadAsync(Station station, IReadOnlyList<S7Item> items, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(items);
        var reference = NextReference();
        var answer = await ExchangeAsync(station, S7JobCodec.Read(reference, items), cancellationToken).ConfigureAwait(false);
        var error = S7AnswerDecoder.TryRead(answer, reference, items, out var header, out var results);
        return error == S7PduError.None ? results : throw AnswerFailure(station, "read", error, header);
    }

    /// <summary>
    /// A write job, sent once: without its acknowledge the CPU may have done it, and FCV = 0 would make it do it again.
    /// Its polls are repeated as a read's (they carry no job). A lost answer is the caller's to settle by a read-back.
    /// </summary>
    public async Task<ImmutableArray<S7ReturnCode>> WriteAsync(Station station, IReadOnlyList<S7WriteItem> items, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(items);
        var reference = NextReference();
        var answer = await ExchangeAsync(station, S7JobCodec.Write(reference, items), JobSending.Once, cancellationToken).ConfigureAwait(false);
        var error = S7AnswerDecoder.TryWrite(answer, reference, items.Count, out var header, out var codes);
        return error == S7PduError.None ? codes : throw AnswerFailure(station, "write", error, header);
    }

    /// <summary>Offers <paramref name="pduSize"/> bytes and returns the PDU size the CPU agrees to.</summary>
    public async Task<int> SetupCommunicationAsync(Station station, int pduSize, CancellationToken cancellationToken)
    {
        var reference = NextReference();
        var answer = await ExchangeAsync(station, S7JobCodec.SetupCommunication(reference, pduSize), cancellationToken).ConfigureAwait(false);
        var error = S7AnswerDecoder.TrySetupCommunication(answer, reference, out var header, out var agreed);
        return error == S7PduError.None ? agreed : throw AnswerFailure(station, "setup communication", error, header);
    }

    /// <summary>
    /// The next PDU reference: from <see cref="PpiMasterOptions.FirstReference"/> on, ... 65535, 1 (0 is left to masters
    /// that do not number their jobs). One sequence for every job this master sends, reads, writes and set-up alike, so
    /// an answer to the previous job never carries the reference of the pending one (docs/ppi.md section 5.1): a link
    /// owns one master per port.
    /// </summary>
    private ushort NextReference()
    {
        _reference = _reference == 0 ? Math.Max(Options.FirstReference, (ushort)1)
            : (ushort)(_reference == ushort.MaxValue ? 1 : _reference + 1);
        return _reference;
    }

    private static PlcCommunicationException AnswerFailure(Station station, string job, S7PduError error, S7Header header) => error switch
    {
        S7PduError.Refused => new PlcCommunicationException(
            PlcErrorKind.NegativeReply, station, $"{station} refused the {job}: error 16#{header.Error:X4} ({S7ErrorText.Describe(header.Error)})"),
        _ => new PlcCommunicationException(PlcErrorKind.FrameCorrupt, station, $"{station} answered the {job} with an unusable PDU: {error}"),
    };
}
