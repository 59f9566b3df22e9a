using System.Collections.Immutable;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// How writes reach the stations of one bus: <see cref="FreeportWriter"/> for the handler's WRITE and WRITE BIT; a PPI
/// link will bring its own (write-var). The polling loop's write queue hands each write here between two exchanges, then
/// logs it with old and new value and publishes the read-back (docs/architecture.md, "Readers").
/// </summary>
internal interface IStationWriter
{
    /// <summary>
    /// Sends <paramref name="request"/> once and judges it by what the PLC holds afterwards; <paramref name="oldRaw"/> is
    /// the last polled value (default when unknown), which settles a lost reply. A link failure is an outcome, never an
    /// exception; cancellation while the write is on the wire throws, so the caller can say so.
    /// </summary>
    Task<WriteResult> WriteAsync(WriteRequest request, ImmutableArray<byte> oldRaw, CancellationToken cancellationToken);
}
