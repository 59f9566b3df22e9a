namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// One way of reading a station's frames: <see cref="PlainReader"/> (READ), <see cref="ListReader"/> (stored lists:
/// DEFINE LIST, READ CHANGES, READ LIST), <see cref="ChangesOfListsReader"/> (all lists in step with one 09). Before
/// each exchange of a cycle, the polling loop asks the station's readers, in the order <see cref="ReaderChoice"/> chose
/// them from the station's IDENTIFY, with the station's frames not read yet in this cycle; the first that takes any
/// reads them. A new way of reading (a protocol v3 handler, a PPI link) is one more reader and one more case in
/// <see cref="ReaderChoice"/>; the loop does not change (docs/architecture.md, "Readers").
/// </summary>
internal interface IStationReader
{
    /// <summary>
    /// Reads what this reader takes of <paramref name="pending"/> (frame indexes into the plan, all of one station, in
    /// plan order) in one exchange, plus the set-up that exchange needs first (DEFINE LIST), and returns each frame it
    /// read with what it brought; empty when it takes none of them now (the loop asks the next reader). A link failure
    /// is a failed <see cref="FrameRead"/>, never an exception. The last reader of every station takes any frame.
    /// </summary>
    Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken);
}
