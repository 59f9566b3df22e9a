namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// The characters put on the wire for one reply and how they were made from the true reply. <see cref="MayBeAccepted"/>
/// is false when no correct decoder may take them as the answer to the request; true only for the untouched reply and
/// for a length change of a reply whose length the request does not fix (READ LIST, READ CHANGES).
/// </summary>
internal sealed record ReplyMutation(byte[] Chars, string How, bool MayBeAccepted);
